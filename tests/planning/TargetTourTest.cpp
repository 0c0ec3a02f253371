// The tour through all target viewpoints: its solver on hand-made distances, the coarse
// grid distances, and the "tour" strategy choosing the first stop of the shortest tour
// where gain over path cost would leave a small region behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/TargetPlanner.hpp"
#include "dynamap/planning/TargetTour.hpp"

namespace dynamap::planning {
namespace {

// Stops on a line at the given x (m); the robot at x = 0, the end of the tour at `end_x`.
TourCosts OnALine(const std::vector<double>& xs, double end_x) {
  TourCosts costs;
  for (const double a : xs) {
    costs.from_robot.push_back(std::abs(a));
    costs.to_end.push_back(std::abs(a - end_x));
    std::vector<double> row;
    for (const double b : xs) row.push_back(std::abs(a - b));
    costs.between.push_back(row);
  }
  return costs;
}

TEST(TargetTour, VisitsEveryStopOnceAndEndsAtTheEnd) {
  const TourCosts costs = OnALine({3.0, -1.0, 7.0, 5.0, -4.0}, 0.0);
  const std::vector<int> order = TourFrom(1, costs);
  ASSERT_EQ(order.size(), 5u);
  EXPECT_EQ(order.front(), 1);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(sorted, (std::vector<int>{0, 1, 2, 3, 4}));
  // From -1: -4, then out to 7 and back home: 1 + 3 + 11 + 7 = 22.
  EXPECT_DOUBLE_EQ(TourLength(order, costs), 22.0);
}

TEST(TargetTour, TheNearWayFirstBeatsGoingFarAndComingBack) {
  // A small region 1 m behind the robot, a large one 6 m ahead.
  // With the end at the robot either order drives the same.
  const std::vector<double> round_trip = TourLengthsByFirstStop(OnALine({6.0, -1.0}, 0.0));
  ASSERT_EQ(round_trip.size(), 2u);
  EXPECT_DOUBLE_EQ(round_trip[0], 6.0 + 7.0 + 1.0);
  EXPECT_DOUBLE_EQ(round_trip[1], 1.0 + 7.0 + 6.0);
  // With the end ahead the small region behind comes first.
  const std::vector<double> towards_end = TourLengthsByFirstStop(OnALine({6.0, -1.0}, 10.0));
  EXPECT_DOUBLE_EQ(towards_end[1], 1.0 + 7.0 + 4.0);
  EXPECT_DOUBLE_EQ(towards_end[0], 6.0 + 7.0 + 11.0);
}

TEST(TargetTour, TwoOptUndoesACrossingThatNearestNeighbourMakes) {
  // Four corners of a 10 x 2 m rectangle, robot and end at the left short side's middle.
  const std::vector<std::pair<double, double>> p = {{0, 1}, {10, 1}, {10, -1}, {0, -1}};
  TourCosts costs;
  for (const auto& a : p) {
    costs.from_robot.push_back(std::hypot(a.first, a.second));
    costs.to_end.push_back(std::hypot(a.first, a.second));
    std::vector<double> row;
    for (const auto& b : p) row.push_back(std::hypot(a.first - b.first, a.second - b.second));
    costs.between.push_back(row);
  }
  // From (0, 1) nearest neighbour goes to (0, -1) first and ends at the far side, 10 m
  // from the end; the tour found goes round the rectangle: 1 + 10 + 2 + 10 + 1 = 24.
  EXPECT_NEAR(TourLength(TourFrom(0, costs), costs), 24.0, 1e-9);
}

TEST(TargetTour, CoarseDistancesFollowTheWayRoundAWall) {
  // 4 x 2 m at 5 cm; a wall at x = 2 m, blocked 0.5 m wide as the inflation leaves it,
  // with a gap at its north end.
  TraversalGrid grid(80, 40, 0.0);
  for (int y = 0; y < 32; ++y) {
    for (int x = 36; x < 46; ++x) grid.penalty[grid.Index({x, y})] = kInfinity;
  }
  const std::vector<std::vector<double>> d =
      CoarseDistances(grid, {{20, 4}}, {{60, 4}, {20, 36}, {40, 10}}, 4, 0.05);
  ASSERT_EQ(d.size(), 1u);
  // Up to the gap and down again (about 3.8 m), not the 2 m straight through the wall.
  EXPECT_GT(d[0][0], 3.4);
  EXPECT_LT(d[0][0], 4.4);
  EXPECT_NEAR(d[0][1], 1.6, 0.25);  // Straight north in the open.
  // A blocked cell stands in with three times the straight line.
  EXPECT_NEAR(d[0][2], 3.0 * std::hypot(20.0, 6.0) * 0.05, 1e-9);
}

void Fill(GridMap* map, int x0, int y0, int x1, int y1, CellState s) {
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) map->Set({x, y}, s);
  }
}

TEST(TargetTour, TourStrategyClearsTheSmallRegionBehindBeforeTheLargeOneAhead) {
  // A corridor 10 x 1 m, known, at 0.1 m; the robot at x = 3 m, the start (where the
  // mission ends) at x = 8 m. Unknown beyond both ends: a small pocket behind the robot,
  // a large area ahead.
  constexpr double kRes = 0.1;
  GridMap map(140, 60, kRes, CellState::kUnknown);
  Fill(&map, 19, 24, 120, 35, CellState::kObstacle);
  Fill(&map, 20, 25, 119, 34, CellState::kNavigable);
  Fill(&map, 19, 27, 19, 32, CellState::kUnknown);  // West end: a small pocket ...
  Fill(&map, 10, 26, 18, 33, CellState::kObstacle);
  Fill(&map, 11, 27, 18, 32, CellState::kUnknown);
  Fill(&map, 120, 25, 120, 34, CellState::kUnknown);  // East end: open unknown.
  CostFieldConfig cost;
  cost.robot_radius_m = 0.2;
  cost.proximity_range_m = 0.2;
  const TraversalGrid grid = BuildTraversalGrid(map, cost);
  TargetPlannerConfig config;
  config.inspection = false;
  config.strategy = "gain";
  const GridIndex robot{50, 30};
  const GridIndex home{100, 30};

  const TargetDecision gain = TargetPlanner(config, kRes).Plan(map, grid, robot, home, nullptr, 0.0);
  ASSERT_EQ(gain.candidates.size(), 2u);
  EXPECT_GT(gain.chosen.region_center.x, 100);  // More to see ahead: gain goes there first.

  config.strategy = "tour";
  const TargetDecision tour = TargetPlanner(config, kRes).Plan(map, grid, robot, home, nullptr, 0.0);
  ASSERT_EQ(tour.candidates.size(), 2u);
  EXPECT_LT(tour.chosen.region_center.x, 30);  // The pocket behind, then ahead, then home.
  EXPECT_DOUBLE_EQ(tour.chosen.score, 1.0);
  for (const TargetCandidate& c : tour.candidates) {
    if (c.region_center.x < 30) continue;
    // Ahead first drives the corridor three times instead of twice.
    EXPECT_GT(c.tour_length_m, tour.chosen.tour_length_m + 5.0);
    EXPECT_LT(c.score, 1.0 / 1.5);  // The selection's switch ratio would take the pocket.
  }
}

}  // namespace
}  // namespace dynamap::planning
