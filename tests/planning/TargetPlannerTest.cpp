// Target planning on synthetic projected maps: frontier regions, the two strategies,
// blacklisting, inspection and completion (return to start, then done).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <tuple>

#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/SqueezePath.hpp"
#include "dynamap/planning/TargetPlanner.hpp"
#include "dynamap/planning/Visibility.hpp"

namespace dynamap::planning {
namespace {

constexpr double kRes = 0.1;

void Fill(GridMap* map, int x0, int y0, int x1, int y1, CellState s) {
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) map->Set({x, y}, s);
  }
}

CostFieldConfig SmallRobot() {
  CostFieldConfig cost;
  cost.robot_radius_m = 0.2;
  cost.proximity_range_m = 0.2;
  return cost;
}

TargetPlannerConfig NoInspection() {
  TargetPlannerConfig config;
  config.inspection = false;
  return config;
}

// A known 4 x 3 m room (cells 10..49 x 10..39) inside unknown space, walls around it,
// with openings: west (small unknown pocket behind it), east (large unknown area), and a
// single unknown cell in the north wall (too small to count).
GridMap RoomWithOpenings() {
  GridMap map(100, 50, kRes, CellState::kUnknown);
  Fill(&map, 9, 9, 50, 40, CellState::kObstacle);
  Fill(&map, 10, 10, 49, 39, CellState::kNavigable);
  Fill(&map, 9, 21, 9, 26, CellState::kUnknown);    // West opening ...
  Fill(&map, 0, 20, 8, 27, CellState::kObstacle);   // ... into a 0.8 x 0.6 m pocket.
  Fill(&map, 1, 21, 8, 26, CellState::kUnknown);
  Fill(&map, 50, 15, 50, 34, CellState::kUnknown);  // East opening into the unknown.
  map.Set({30, 40}, CellState::kUnknown);           // Pinhole in the north wall.
  Fill(&map, 29, 41, 31, 41, CellState::kObstacle);
  map.Set({30, 41}, CellState::kObstacle);
  return map;
}

TEST(TargetPlanner, FindsFrontierRegionsAndDropsSmallOnes) {
  const GridMap map = RoomWithOpenings();
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  const TargetPlanner planner(NoInspection(), kRes);
  const TargetDecision d = planner.Plan(map, grid, {15, 24}, {15, 24}, nullptr, 0.0);
  EXPECT_EQ(d.frontier_regions, 3);
  ASSERT_EQ(d.candidates.size(), 2u);  // West and east; the pinhole's region is dropped.
  EXPECT_EQ(d.kind, TargetKind::kFrontier);
  // The east opening reveals far more unknown area; it wins under gain over path cost.
  EXPECT_GT(d.chosen.region_center.x, 40);
  for (const TargetCandidate& c : d.candidates) {
    EXPECT_FALSE(grid.Blocked(c.viewpoint));
    EXPECT_GT(c.gain, 0.0);
  }
}

TEST(TargetPlanner, NearestFrontierStrategyTakesTheClosestRegion) {
  const GridMap map = RoomWithOpenings();
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  TargetPlannerConfig config = NoInspection();
  config.strategy = "nearest-frontier";
  const TargetDecision d = TargetPlanner(config, kRes).Plan(map, grid, {15, 24}, {15, 24}, nullptr, 0.0);
  ASSERT_EQ(d.kind, TargetKind::kFrontier);
  EXPECT_LT(d.chosen.region_center.x, 15);  // The west pocket, although it shows less.
}

TEST(TargetPlanner, NearestFrontierLooksFromWhereTheUnknownBeyondIsSeen) {
  // A known corridor (y 10..19) with a doorway (x 40..44) through its thick north wall into
  // an unknown room. The cheapest viewpoint that sees the doorway's centre lies down the
  // corridor and sees the room edge-on past the jamb, hardly at all: the robot would drive
  // there, look, see next to nothing and blacklist the room. The nearest frontier takes the
  // cheapest viewpoint from which enough of the room is seen.
  GridMap map(80, 60, kRes, CellState::kUnknown);
  Fill(&map, 0, 9, 79, 22, CellState::kObstacle);
  Fill(&map, 1, 10, 78, 19, CellState::kNavigable);
  Fill(&map, 40, 20, 44, 22, CellState::kNavigable);  // The doorway.
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  TargetPlannerConfig config = NoInspection();
  config.strategy = "nearest-frontier";
  config.viewpoint_radius_m = 2.5;
  config.min_gain_m2 = 1.0;
  const TargetDecision d = TargetPlanner(config, kRes).Plan(map, grid, {5, 15}, {5, 15}, nullptr, 0.0);
  ASSERT_EQ(d.kind, TargetKind::kFrontier);
  EXPECT_GE(d.chosen.gain, 1.0);
  EXPECT_FALSE(grid.Blocked(d.chosen.viewpoint));
  // Asking for no gain at all gives the first viewpoint: down the corridor, seeing the
  // room past the jamb through a ray or two.
  config.min_gain_m2 = 0.0;
  const TargetDecision blind =
      TargetPlanner(config, kRes).Plan(map, grid, {5, 15}, {5, 15}, nullptr, 0.0);
  ASSERT_EQ(blind.kind, TargetKind::kFrontier);
  EXPECT_LT(blind.chosen.gain, 1.0);
  EXPECT_LT(blind.chosen.viewpoint.x, d.chosen.viewpoint.x);  // The seeing one is nearer the door.
}

TEST(TargetPlanner, EveryStrategyLooksIntoARoomGlimpsedPastAJamb) {
  // The corridor and doorway above: the first viewpoint found sees the room through a ray
  // or two. Gain and tour weigh what a viewpoint sees, and dropped the room for it, so
  // with nothing else unknown the map was done with a room never entered.
  GridMap map(80, 60, kRes, CellState::kUnknown);
  Fill(&map, 0, 9, 79, 22, CellState::kObstacle);
  Fill(&map, 1, 10, 78, 19, CellState::kNavigable);
  Fill(&map, 40, 20, 44, 22, CellState::kNavigable);
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  for (const char* strategy : {"gain", "tour"}) {
    TargetPlannerConfig config = NoInspection();
    config.strategy = strategy;
    config.viewpoint_radius_m = 2.5;
    config.min_gain_m2 = 1.0;
    const TargetDecision d =
        TargetPlanner(config, kRes).Plan(map, grid, {5, 15}, {5, 15}, nullptr, 0.0);
    ASSERT_EQ(d.kind, TargetKind::kFrontier) << strategy;
    EXPECT_GE(d.chosen.gain, 1.0) << strategy;
    EXPECT_FALSE(grid.Blocked(d.chosen.viewpoint)) << strategy;
  }
}

TEST(TargetPlanner, BlacklistedTargetsAreSkippedUntilTheyExpire) {
  const GridMap map = RoomWithOpenings();
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  TargetPlanner planner(NoInspection(), kRes);
  const TargetDecision first = planner.Plan(map, grid, {15, 24}, {15, 24}, nullptr, 0.0);
  ASSERT_EQ(first.kind, TargetKind::kFrontier);
  planner.ReportFailure(first.chosen, 1.0);  // One failure is forgiven ...
  EXPECT_EQ(planner.Plan(map, grid, {15, 24}, {15, 24}, nullptr, 2.0).cell, first.cell);
  planner.ReportFailure(first.chosen, 3.0);  // ... the second blacklists the place.
  const TargetDecision second = planner.Plan(map, grid, {15, 24}, {15, 24}, nullptr, 4.0);
  ASSERT_EQ(second.kind, TargetKind::kFrontier);
  EXPECT_NE(second.chosen.region_center, first.chosen.region_center);
  const double later = 3.0 + planner.config().blacklist.duration_s + 1.0;
  EXPECT_EQ(planner.Plan(map, grid, {15, 24}, {15, 24}, nullptr, later).cell, first.cell);
}

TEST(TargetBlacklist, APlaceThatKeepsFailingIsBlacklistedLongerEachTime) {
  TargetBlacklistConfig config;
  config.duration_s = 10.0;
  config.max_duration_s = 30.0;
  config.max_failures = 1;
  TargetBlacklist blacklist(config, kRes);
  const GridIndex place{20, 20};
  blacklist.ReportFailure(place, 0.0);
  EXPECT_TRUE(blacklist.IsBlacklisted(place, 9.9));
  EXPECT_FALSE(blacklist.IsBlacklisted(place, 10.0));
  blacklist.ReportFailure(place, 10.0);  // Again: 20 s.
  EXPECT_TRUE(blacklist.IsBlacklisted(place, 29.9));
  EXPECT_FALSE(blacklist.IsBlacklisted(place, 30.0));
  blacklist.Blacklist(place, 30.0);      // And again: 40 s, capped at 30 s.
  blacklist.Blacklist(place, 35.0);      // While banned, the ban stands as it is.
  EXPECT_TRUE(blacklist.IsBlacklisted(place, 59.9));
  EXPECT_FALSE(blacklist.IsBlacklisted(place, 60.0));
  // Another place starts again at the base duration.
  blacklist.Blacklist({40, 20}, 60.0);
  EXPECT_FALSE(blacklist.IsBlacklisted({40, 20}, 70.0));
}

TEST(TargetBlacklist, EachPlaceIsLetOffOnceForALastTry) {
  TargetBlacklistConfig config;
  config.max_failures = 1;
  TargetBlacklist blacklist(config, kRes);
  const GridIndex place{20, 20};
  blacklist.ReportFailure(place, 0.0);
  blacklist.Blacklist({40, 20}, 1.0);
  EXPECT_EQ(blacklist.LiftBansForALastTry(2.0), 2);
  EXPECT_FALSE(blacklist.IsBlacklisted(place, 2.0));
  EXPECT_FALSE(blacklist.IsBlacklisted({40, 20}, 2.0));
  blacklist.ReportFailure(place, 3.0);  // The last try failed too: banned for good this time.
  EXPECT_EQ(blacklist.LiftBansForALastTry(4.0), 0);
  EXPECT_TRUE(blacklist.IsBlacklisted(place, 4.0));
  blacklist.Blacklist({20, 40}, 5.0);   // A place banned for the first time gets its try.
  EXPECT_EQ(blacklist.LiftBansForALastTry(6.0), 1);
  EXPECT_FALSE(blacklist.IsBlacklisted({20, 40}, 6.0));
  EXPECT_EQ(blacklist.ActiveCount(6.0), 1);
}

TEST(TargetPlanner, BlacklistedRegionsAreTriedOnceMoreBeforeGoingHome) {
  const GridMap map = RoomWithOpenings();
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  TargetPlannerConfig config = NoInspection();
  config.blacklist.max_failures = 1;
  config.blacklist.duration_s = 1000.0;  // Longer than the mission.
  TargetPlanner planner(config, kRes);
  const GridIndex robot{15, 24};
  const GridIndex home{30, 24};
  TargetDecision d = planner.Plan(map, grid, robot, home, nullptr, 0.0);
  std::vector<GridIndex> regions;
  for (double t = 1.0; d.kind == TargetKind::kFrontier && t < 20.0; t += 1.0) {
    regions.push_back(d.chosen.region_center);
    planner.ReportFailure(d.chosen, t);
    d = planner.Plan(map, grid, robot, home, nullptr, t);
  }
  ASSERT_GE(regions.size(), 2u);
  ASSERT_EQ(d.kind, TargetKind::kReturnToStart);  // Every region banned: home.
  EXPECT_EQ(d.blacklisted_regions, static_cast<int>(regions.size()));
  // Named for the report.
  ASSERT_EQ(d.blacklisted_frontiers.size(), regions.size());
  EXPECT_TRUE(std::is_permutation(regions.begin(), regions.end(), d.blacklisted_frontiers.begin()));
  EXPECT_TRUE(d.unreachable_frontiers.empty());
  EXPECT_EQ(planner.LiftBansForALastTry(d, 30.0), static_cast<int>(regions.size()));
  d = planner.Plan(map, grid, robot, home, nullptr, 30.0);
  ASSERT_EQ(d.kind, TargetKind::kFrontier);  // One more try each ...
  const GridIndex failed_again = d.chosen.region_center;
  planner.ReportFailure(d.chosen, 31.0);
  d = planner.Plan(map, grid, robot, home, nullptr, 31.0);
  // ... but only one: a region failing its last try stays banned.
  EXPECT_EQ(d.blacklisted_regions, 1);
  ASSERT_EQ(d.kind, TargetKind::kFrontier);
  for (const TargetCandidate& c : d.candidates) EXPECT_NE(c.region_center, failed_again);
  EXPECT_EQ(planner.LiftBansForALastTry(d, 32.0), 0);  // Candidates are left.

  // Switched off, and never for the nearest frontier (the plain baseline).
  TargetPlannerConfig off = config;
  off.blacklist.last_try = false;
  TargetPlannerConfig nearest = config;
  nearest.strategy = "nearest-frontier";
  for (const TargetPlannerConfig& c : {off, nearest}) {
    TargetPlanner without(c, kRes);
    TargetDecision w = without.Plan(map, grid, robot, home, nullptr, 0.0);
    for (double t = 1.0; w.kind == TargetKind::kFrontier && t < 20.0; t += 1.0) {
      without.ReportFailure(w.chosen, t);
      w = without.Plan(map, grid, robot, home, nullptr, t);
    }
    ASSERT_EQ(w.kind, TargetKind::kReturnToStart) << c.strategy;
    EXPECT_GE(w.blacklisted_regions, 2) << c.strategy;
    EXPECT_EQ(without.LiftBansForALastTry(w, 30.0), 0) << c.strategy;
  }
}

TEST(TargetPlanner, UnreachableFrontierIsNotATarget) {
  GridMap map = RoomWithOpenings();
  Fill(&map, 40, 10, 40, 39, CellState::kObstacle);  // Wall off the east part.
  Fill(&map, 9, 21, 9, 26, CellState::kObstacle);    // Close the west opening.
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  const TargetDecision d =
      TargetPlanner(NoInspection(), kRes).Plan(map, grid, {20, 24}, {12, 24}, nullptr, 0.0);
  EXPECT_EQ(d.unreachable_regions, 1);
  EXPECT_EQ(d.kind, TargetKind::kReturnToStart);
  // Named for the report: the east opening's region, beyond the wall.
  ASSERT_EQ(d.unreachable_frontiers.size(), 1u);
  EXPECT_GT(d.unreachable_frontiers[0].x, 40);
  EXPECT_TRUE(d.blacklisted_frontiers.empty());
}

TEST(TargetPlanner, FullyExploredMapMeansReturnToStartThenDone) {
  GridMap map(60, 40, kRes, CellState::kObstacle);
  Fill(&map, 1, 1, 58, 38, CellState::kNavigable);
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  const TargetPlanner planner(NoInspection(), kRes);
  const GridIndex home{10, 10};
  const TargetDecision away = planner.Plan(map, grid, {40, 30}, home, nullptr, 0.0);
  EXPECT_EQ(away.kind, TargetKind::kReturnToStart);
  EXPECT_EQ(away.cell, home);
  EXPECT_EQ(planner.Plan(map, grid, {11, 10}, home, nullptr, 0.0).kind, TargetKind::kDone);
}

TEST(TargetPlanner, InspectionTargetsLeadToEverySurfaceUntilDone) {
  // A known 8 x 6 m room with a pillar: walls far from the start must be seen from within
  // the inspection distance before the mission can end.
  GridMap map(80, 60, kRes, CellState::kObstacle);
  Fill(&map, 1, 1, 78, 58, CellState::kNavigable);
  Fill(&map, 38, 28, 41, 31, CellState::kObstacle);
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  TargetPlannerConfig config;
  const TargetPlanner planner(config, kRes);
  SurfaceCoverage coverage;
  const GridIndex home{5, 5};
  robotio::Pose2D pose{map.CenterX(5), map.CenterY(5), 0.0};
  coverage.Observe(map, pose);
  int visits = 0;
  TargetDecision d;
  for (; visits < 40; ++visits) {
    d = planner.Plan(map, grid, map.CellAt(pose.x, pose.y), home, &coverage, 0.0);
    if (d.kind != TargetKind::kInspection) break;
    // Drive there and look at the region (turning on the spot towards it).
    const GridIndex c = d.chosen.region_center;
    pose = {map.CenterX(d.cell.x), map.CenterY(d.cell.y), 0.0};
    pose.theta = std::atan2(map.CenterY(c.y) - pose.y, map.CenterX(c.x) - pose.x);
    coverage.Observe(map, pose);
  }
  EXPECT_GT(visits, 1);
  EXPECT_LT(visits, 40);
  EXPECT_EQ(d.kind, TargetKind::kReturnToStart);
  EXPECT_GT(coverage.Fraction(map), 0.9);
}

TEST(TargetPlanner, FrontiersFirstLeavesWallsForWhenNoFrontierIsLeft) {
  const GridMap map = RoomWithOpenings();
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  const SurfaceCoverage nothing_seen;
  TargetPlannerConfig frontiers_first;
  frontiers_first.frontiers_first = true;
  const TargetDecision first =
      TargetPlanner(frontiers_first, kRes).Plan(map, grid, {15, 24}, {15, 24}, &nothing_seen, 0.0);
  ASSERT_FALSE(first.candidates.empty());
  for (const TargetCandidate& c : first.candidates) EXPECT_EQ(c.kind, TargetKind::kFrontier);
  const TargetDecision both =  // The default: both kinds compete on score.
      TargetPlanner(TargetPlannerConfig{}, kRes).Plan(map, grid, {15, 24}, {15, 24}, &nothing_seen, 0.0);
  EXPECT_TRUE(std::any_of(both.candidates.begin(), both.candidates.end(),
                          [](const TargetCandidate& c) { return c.kind == TargetKind::kInspection; }));
}

TEST(TargetPlanner, FrontierViewpointsKeepTheFloorBlindDistance) {
  // Unseen floor next to a frontier is visible only from beyond the Kinects' floor blind
  // radius: with a minimum view distance the viewpoint keeps it, and what is counted as
  // gain is what lies beyond it.
  const GridMap map = RoomWithOpenings();
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  TargetPlannerConfig config = NoInspection();
  config.min_view_distance_m = 1.2;
  const TargetPlanner planner(config, kRes);
  const TargetDecision d = planner.Plan(map, grid, {45, 24}, {15, 24}, nullptr, 0.0);
  ASSERT_FALSE(d.candidates.empty());
  const TargetPlanner plain(NoInspection(), kRes);
  const TargetDecision near = plain.Plan(map, grid, {45, 24}, {15, 24}, nullptr, 0.0);
  for (const TargetCandidate& c : d.candidates) {
    const double distance = std::hypot(c.viewpoint.x - c.region_center.x,
                                       c.viewpoint.y - c.region_center.y) * kRes;
    EXPECT_GE(distance, 1.2 - 1e-9);
    EXPECT_LE(distance, 1.2 + config.viewpoint_radius_m + 1e-9);
  }
  // Without it the robot, 0.5 m from the east opening, would take its own cell.
  ASSERT_FALSE(near.candidates.empty());
  EXPECT_LT(std::hypot(near.chosen.viewpoint.x - 45, near.chosen.viewpoint.y - 24) * kRes, 0.5);
}

TEST(TargetPlanner, ARoomSeenFromAfarThroughADoorwayIsLookedIntoFromInFrontOfIt) {
  // A known corridor (y 10..19) and, through a doorway in its north wall, a strip of room
  // floor seen from afar (x 38..45, y 21..50) in unknown space. The doorway (0.2 m) does not
  // let the robot through yet, so no cell near the room's frontier is reachable: the
  // viewpoint is the corridor cell nearest to it that sees it, in front of the doorway.
  GridMap map(80, 60, kRes, CellState::kUnknown);
  Fill(&map, 0, 9, 79, 20, CellState::kObstacle);
  Fill(&map, 1, 10, 78, 19, CellState::kNavigable);
  Fill(&map, 40, 20, 41, 20, CellState::kNavigable);  // The doorway.
  Fill(&map, 38, 21, 45, 50, CellState::kNavigable);  // Room floor seen through it.
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  ASSERT_TRUE(grid.Blocked({40, 20}) && grid.Blocked({41, 20}));
  const TargetDecision d =
      TargetPlanner(NoInspection(), kRes).Plan(map, grid, {10, 15}, {10, 15}, nullptr, 0.0);
  ASSERT_EQ(d.kind, TargetKind::kFrontier);
  EXPECT_GT(d.chosen.region_center.y, 21);  // A frontier of the room, ...
  EXPECT_FALSE(grid.Blocked(d.chosen.viewpoint));
  EXPECT_LE(d.chosen.viewpoint.y, 19);       // ... looked at from the corridor ...
  EXPECT_NEAR(d.chosen.viewpoint.x, 41, 3);  // ... right in front of the doorway.
  EXPECT_GT(d.chosen.gain, 0.0);
  // The nearest frontier goes there too, even when nothing reachable sees enough of the
  // room: standing in front of the doorway makes its threshold known floor.
  TargetPlannerConfig nearest = NoInspection();
  nearest.strategy = "nearest-frontier";
  nearest.min_gain_m2 = 100.0;
  const TargetDecision n =
      TargetPlanner(nearest, kRes).Plan(map, grid, {10, 15}, {10, 15}, nullptr, 0.0);
  ASSERT_EQ(n.kind, TargetKind::kFrontier);
  EXPECT_LE(n.chosen.viewpoint.y, 19);
  EXPECT_NEAR(n.chosen.viewpoint.x, 41, 3);
}

TEST(TargetPlanner, ARoomBehindADoorwayOnlyTheSqueezePassesIsPlannedFor) {
  // The office's N2 (seed 2, edge clearance 1.5): a corridor (y 10..29), and north of it,
  // through a doorway mapped 0.75 m between obstacle cell centres (x 51..64 at y = 30; the
  // open leaf and the post), a room (x 45..70) known up to y = 70 and unknown beyond. The
  // robot's full radius closes the doorway; the radius less half a cell does not, and the
  // path planner squeezes through it then. Without the squeeze grid the room's frontier is
  // only looked at from the corridor; with it the viewpoint lies in the room.
  constexpr double kCell = 0.05;
  GridMap map(120, 110, kCell, CellState::kUnknown);
  Fill(&map, 0, 9, 119, 30, CellState::kObstacle);
  Fill(&map, 1, 10, 118, 29, CellState::kNavigable);
  Fill(&map, 44, 31, 71, 70, CellState::kObstacle);
  Fill(&map, 45, 31, 70, 70, CellState::kNavigable);
  Fill(&map, 51, 30, 64, 30, CellState::kNavigable);  // The doorway.
  const CostFieldConfig cost;  // The office robot: 0.36 m.
  const TraversalGrid grid = BuildTraversalGrid(map, cost);
  const TraversalGrid squeeze = BuildSqueezeGrid(map, cost);
  for (int x = 51; x <= 64; ++x) ASSERT_TRUE(grid.Blocked({x, 30}));
  const GridIndex robot{20, 20};
  const TargetPlanner planner(NoInspection(), kCell);

  const TargetDecision without = planner.Plan(map, grid, robot, robot, nullptr, 0.0);
  ASSERT_EQ(without.kind, TargetKind::kFrontier);
  EXPECT_LT(without.chosen.viewpoint.y, 30);  // From the corridor, through the doorway.

  const TargetDecision with = planner.Plan(map, grid, robot, robot, nullptr, 0.0, &squeeze);
  ASSERT_EQ(with.kind, TargetKind::kFrontier);
  EXPECT_GT(with.chosen.region_center.y, 60);
  EXPECT_GT(with.chosen.viewpoint.y, 30);  // In the room ...
  EXPECT_GE(with.chosen.gain, TargetPlannerConfig{}.min_gain_m2);
  const auto path = FindSqueezePath(map, cost, robot, with.chosen.viewpoint);
  ASSERT_TRUE(path.has_value());  // ... which the path planner reaches by squeezing.
  EXPECT_EQ(path->path.cells.back(), with.chosen.viewpoint);

  // Where the full radius has a way, the squeeze grid changes nothing.
  GridMap open = map;
  Fill(&open, 46, 30, 69, 30, CellState::kNavigable);
  const TraversalGrid open_grid = BuildTraversalGrid(open, cost);
  const TraversalGrid open_squeeze = BuildSqueezeGrid(open, cost);
  const TargetDecision a = planner.Plan(open, open_grid, robot, robot, nullptr, 0.0);
  const TargetDecision b = planner.Plan(open, open_grid, robot, robot, nullptr, 0.0, &open_squeeze);
  EXPECT_EQ(a.chosen.viewpoint, b.chosen.viewpoint);
  EXPECT_GT(a.chosen.viewpoint.y, 30);
}

TEST(TargetPlanner, SurfacesAreLookedAtFromWhereTheFullRadiusStandsFree) {
  // A corridor (y 20..39) with, to the east, a 3.9 m niche 0.75 m between obstacle cell
  // centres (a desk beside a wall) and, to the north, a room behind a doorway as narrow.
  // Only the squeeze radius gets into either. The room's far walls are looked at from
  // inside the room, where the robot stands free; the niche's far end from nowhere: the
  // 0.72 m base would have to drive 3 m with centimetres to spare to look at it.
  constexpr double kCell = 0.05;
  GridMap map(200, 100, kCell, CellState::kObstacle);
  Fill(&map, 1, 20, 120, 39, CellState::kNavigable);   // Corridor.
  Fill(&map, 121, 23, 198, 36, CellState::kNavigable);  // Niche.
  Fill(&map, 41, 41, 79, 94, CellState::kNavigable);    // Room ...
  Fill(&map, 51, 40, 64, 40, CellState::kNavigable);    // ... and its doorway.
  const CostFieldConfig cost;  // The office robot: 0.36 m.
  const TraversalGrid grid = BuildTraversalGrid(map, cost);
  const TraversalGrid squeeze = BuildSqueezeGrid(map, cost);
  ASSERT_TRUE(grid.Blocked({58, 40}) && grid.Blocked({150, 30}));
  ASSERT_FALSE(squeeze.Blocked({58, 40}) || squeeze.Blocked({150, 30}));
  // Visit inspection targets until none is left, looking at each region from its
  // viewpoint as the runtime does.
  const TargetPlanner planner(TargetPlannerConfig{}, kCell);
  const GridIndex home{20, 30};
  robotio::Pose2D pose{map.CenterX(home.x), map.CenterY(home.y), 0.0};
  SurfaceCoverage coverage;
  coverage.Observe(map, pose);
  int in_room = 0;
  TargetDecision d;
  for (int visits = 0; visits < 60; ++visits) {
    d = planner.Plan(map, grid, map.CellAt(pose.x, pose.y), home, &coverage, 0.0, &squeeze);
    if (d.kind != TargetKind::kInspection) break;
    EXPECT_FALSE(grid.Blocked(d.cell)) << d.cell.x << ", " << d.cell.y;
    EXPECT_LE(d.cell.x, 120);
    if (d.cell.y > 40) ++in_room;
    const GridIndex c = d.chosen.region_center;
    pose = {map.CenterX(d.cell.x), map.CenterY(d.cell.y), 0.0};
    pose.theta = std::atan2(map.CenterY(c.y) - pose.y, map.CenterX(c.x) - pose.x);
    coverage.Observe(map, pose);
  }
  EXPECT_EQ(d.kind, TargetKind::kReturnToStart);
  EXPECT_GT(in_room, 0);
  // The room's far wall was seen from close by; the niche's far end was not.
  EXPECT_TRUE(coverage.InspectedNear(map, {60, 95}));
  EXPECT_FALSE(coverage.InspectedNear(map, {199, 30}));
}

TEST(TargetPlanner, ADeskMappedAsASpeckledBlockIsLookedAtAlongItsEdge) {
  // A desk whose top the Kinects saw in specks: floor cells inside its block make the
  // inside specks surfaces, connected to its edge, and the region's centre one of those
  // specks, which no viewpoint sees. The edge is looked at all the same.
  GridMap map(80, 60, kRes, CellState::kObstacle);
  Fill(&map, 1, 1, 78, 58, CellState::kNavigable);
  Fill(&map, 30, 40, 49, 45, CellState::kObstacle);  // The desk, 2 x 0.6 m ...
  for (const GridIndex hole : {GridIndex{38, 42}, GridIndex{40, 43}, GridIndex{42, 42},
                               GridIndex{34, 43}, GridIndex{46, 42}}) {
    map.Set(hole, CellState::kNavigable);  // ... with floor seen between its specks.
  }
  const TraversalGrid grid = BuildTraversalGrid(map, SmallRobot());
  // Everything seen closely but the desk.
  SurfaceCoverage coverage;
  for (const auto& [x, y, theta] : {std::tuple{10, 10, 0.0}, std::tuple{10, 10, M_PI / 2},
                                     std::tuple{10, 10, M_PI}, std::tuple{10, 10, -M_PI / 2},
                                     std::tuple{70, 50, 0.0}, std::tuple{70, 50, M_PI / 2},
                                     std::tuple{70, 10, 0.0}, std::tuple{70, 10, -M_PI / 2},
                                     std::tuple{10, 50, M_PI}, std::tuple{10, 50, M_PI / 2},
                                     std::tuple{40, 55, M_PI / 2}, std::tuple{40, 5, -M_PI / 2}}) {
    GridMap walls_only = map;
    Fill(&walls_only, 30, 40, 49, 45, CellState::kNavigable);
    coverage.Observe(walls_only, {map.CenterX(x), map.CenterY(y), theta});
  }
  const TargetDecision d = TargetPlanner(TargetPlannerConfig{}, kRes)
                               .Plan(map, grid, {10, 10}, {10, 10}, &coverage, 0.0);
  const auto desk = std::find_if(d.candidates.begin(), d.candidates.end(), [](const auto& c) {
    return c.region_center.x >= 30 && c.region_center.x <= 49 && c.region_center.y >= 40 &&
           c.region_center.y <= 45;
  });
  ASSERT_NE(desk, d.candidates.end());
  EXPECT_EQ(desk->kind, TargetKind::kInspection);
  EXPECT_FALSE(grid.Blocked(desk->viewpoint));
  EXPECT_GE(desk->gain, TargetPlannerConfig{}.min_inspection_m);

  // Looking at that cell keeps failing: it is blacklisted, and another of the desk's
  // cells is looked at instead, until every one tried has failed.
  TargetPlanner planner(TargetPlannerConfig{}, kRes);
  const auto on_desk = [](const TargetCandidate& c) {
    return c.region_center.x >= 30 && c.region_center.x <= 49 && c.region_center.y >= 40 &&
           c.region_center.y <= 45;
  };
  std::vector<GridIndex> looked_at;
  for (int round = 0; round < 10; ++round) {
    const TargetDecision next = planner.Plan(map, grid, {10, 10}, {10, 10}, &coverage, 1.0);
    const auto it = std::find_if(next.candidates.begin(), next.candidates.end(), on_desk);
    if (it == next.candidates.end()) break;
    for (const GridIndex& earlier : looked_at) EXPECT_NE(it->region_center, earlier);
    looked_at.push_back(it->region_center);
    planner.ReportFailure(*it, 1.0);
    planner.ReportFailure(*it, 1.0);
  }
  EXPECT_GE(looked_at.size(), 2u);
  EXPECT_LT(looked_at.size(), 10u);
}

TEST(SurfaceCoverage, AWallThatShiftsByOneCellStaysInspected) {
  GridMap map(40, 40, kRes, CellState::kNavigable);
  Fill(&map, 30, 0, 30, 39, CellState::kObstacle);  // A wall at x = 30.
  SurfaceCoverage coverage;
  coverage.Observe(map, {map.CenterX(20), map.CenterY(20), 0.0});  // 1 m away, facing it.
  EXPECT_GT(coverage.Fraction(map), 0.5);  // The part within the view cone ...
  EXPECT_LT(coverage.Fraction(map), 0.95);  // ... and not the ends.
  ASSERT_TRUE(coverage.Inspected(map.Index({30, 20})));
  // The map firms up: the wall's face is one cell nearer now.
  Fill(&map, 29, 0, 29, 39, CellState::kObstacle);
  EXPECT_FALSE(coverage.Inspected(map.Index({29, 20})));
  EXPECT_TRUE(coverage.InspectedNear(map, {29, 20}));
  EXPECT_FALSE(coverage.InspectedNear(map, {29, 39}));  // Out of the cone then and now.
}

TEST(Visibility, CellsNearerThanTheMinimumRangeAreNotSeen) {
  GridMap map(60, 60, kRes, CellState::kUnknown);
  ViewCone cone;
  cone.range_m = 2.0;
  cone.min_range_m = 1.0;
  const std::vector<int> seen = VisibleCells(map, {30, 30}, cone);
  ASSERT_FALSE(seen.empty());
  for (const int i : seen) {
    const GridIndex c = map.Cell(i);
    const double d = std::hypot(c.x - 30, c.y - 30) * kRes;
    EXPECT_GE(d, 1.0 - 1.5 * kRes);
    EXPECT_LE(d, 2.0 + 1.5 * kRes);
  }
}

}  // namespace
}  // namespace dynamap::planning
