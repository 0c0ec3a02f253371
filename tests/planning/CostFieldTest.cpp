#include "dynamap/planning/CostField.hpp"

#include <gtest/gtest.h>

#include "dynamap/planning/AStar.hpp"

namespace dynamap::planning {
namespace {

constexpr double kRes = 0.05;

// Two known rooms joined by a 0.9 m doorway in a wall along y = 40; on the far side, the
// floor in the shadow of the east door post was never seen (a 0.6 x 0.3 m unknown patch
// reaching 0.3 m into the doorway's width).
GridMap Doorway() {
  GridMap map(80, 80, kRes, CellState::kNavigable);
  for (int x = 0; x < 80; ++x) {
    if (x < 31 || x >= 49) map.Set({x, 40}, CellState::kObstacle);  // Gap: cells 31..48.
  }
  for (int y = 41; y < 47; ++y) {
    for (int x = 43; x < 55; ++x) map.Set({x, y}, CellState::kUnknown);
  }
  return map;
}

TEST(BuildTraversalGrid, UnseenFloorBesideADoorPostDoesNotCloseTheDoorway) {
  const TraversalGrid grid = BuildTraversalGrid(Doorway(), CostFieldConfig{});
  EXPECT_TRUE(AStarSearch(grid, {40, 20}, {40, 60}).found);
  // The unknown patch itself and a band of unknown_radius_m around it stay blocked.
  EXPECT_TRUE(grid.Blocked(GridIndex{50, 43}));
  EXPECT_TRUE(grid.Blocked(GridIndex{41, 43}));
  EXPECT_FALSE(grid.Blocked(GridIndex{38, 43}));
}

TEST(BuildTraversalGrid, InflatingUnknownLikeObstaclesWouldCloseIt) {
  CostFieldConfig config;
  config.unknown_radius_m = config.robot_radius_m;
  EXPECT_FALSE(AStarSearch(BuildTraversalGrid(Doorway(), config), {40, 20}, {40, 60}).found);
}

TEST(BuildTraversalGrid, ObstaclesInflateByTheRobotRadiusWithAPenaltyBeyond) {
  const CostFieldConfig config;
  const TraversalGrid grid = BuildTraversalGrid(Doorway(), config);
  EXPECT_TRUE(grid.Blocked(GridIndex{20, 34}));   // 0.30 m from the wall.
  EXPECT_FALSE(grid.Blocked(GridIndex{20, 32}));  // 0.40 m: free, but penalised.
  EXPECT_GT(grid.penalty[grid.Index({20, 32})], 0.0);
  EXPECT_EQ(grid.penalty[grid.Index({20, 10})], 0.0);  // 1.5 m away.
}

TEST(BuildTraversalGrid, AStairPitIsKeptFurtherAwayThanAWall) {
  // A wall along y = 0..1, and 0.8 m from it a block (x < 30) or a pit (x >= 30): the
  // robot fits between wall and block, not between wall and pit.
  GridMap map(60, 60, kRes, CellState::kNavigable);
  for (int x = 0; x < 60; ++x) {
    map.Set({x, 0}, CellState::kObstacle);
    map.Set({x, 1}, CellState::kObstacle);
    for (int y = 17; y < 60; ++y) map.Set({x, y}, x < 30 ? CellState::kObstacle : CellState::kHole);
  }
  const auto passable_across = [](const TraversalGrid& grid, int x) {
    for (int y = 2; y < 17; ++y) {
      if (!grid.Blocked({x, y})) return true;
    }
    return false;
  };
  CostFieldConfig config;
  const TraversalGrid grid = BuildTraversalGrid(map, config);
  EXPECT_TRUE(passable_across(grid, 10));
  EXPECT_FALSE(passable_across(grid, 50));
  EXPECT_TRUE(grid.Blocked({50, 8}));  // 0.45 m from the pit: too near.
  config.hole_margin_m = 0.0;
  EXPECT_TRUE(passable_across(BuildTraversalGrid(map, config), 50));
}

// A 3 x 3 m pit at x, y >= 1.5 m on a 4.5 m floor, and the robot 0.40 m west of its edge
// (within the 0.56 m the margin keeps): as a pit's edge seen late leaves it.
GridMap PitCorner() {
  GridMap map(90, 90, kRes, CellState::kNavigable);
  for (int y = 30; y < 90; ++y) {
    for (int x = 30; x < 90; ++x) map.Set({x, y}, CellState::kHole);
  }
  return map;
}

TEST(FreeWayOut, ARobotInsideAPitsMarginGetsAWayOutThatNeverNearsThePit) {
  const GridMap map = PitCorner();
  const CostFieldConfig config;
  const GridIndex robot{22, 50};  // 0.40 m from the pit's west edge (cell 30).
  TraversalGrid grid = BuildTraversalGrid(map, config);
  ASSERT_TRUE(grid.Blocked(robot));
  TraversalGrid standing = grid;
  FreeStandingCell(standing, robot);
  EXPECT_FALSE(AStarSearch(standing, robot, {5, 50}).found);  // Walled in: the old way.

  FreeWayOut(grid, map, robot, config);
  const GridPath path = AStarSearch(grid, robot, {5, 50});
  ASSERT_TRUE(path.found);
  for (const GridIndex& c : path.cells) EXPECT_LE(c.x, robot.x) << c.x << ", " << c.y;
  // Nothing nearer the pit than the robot opened, nor farther than the margin's reach.
  EXPECT_TRUE(grid.Blocked(GridIndex{23, 50}));
  EXPECT_TRUE(grid.Blocked(GridIndex{22, 30}));  // Beside the pit's corner, 1 m away.
  EXPECT_FALSE(grid.Blocked(GridIndex{21, 50}));
  EXPECT_EQ(grid.penalty[grid.Index({21, 50})], kStandingCellPenalty);
}

TEST(FreeWayOut, NoWallCellOpensAndAPassableRobotChangesNothing) {
  const GridMap map = Doorway();  // A wall along y = 40.
  const CostFieldConfig config;
  const GridIndex robot{20, 37};  // 0.15 m from the wall.
  TraversalGrid grid = BuildTraversalGrid(map, config);
  FreeWayOut(grid, map, robot, config);
  EXPECT_TRUE(AStarSearch(grid, robot, {20, 10}).found);
  for (int x = 0; x < 80; ++x) {
    if (x < 31 || x >= 49) {
      EXPECT_TRUE(grid.Blocked(GridIndex{x, 40})) << x;
    }
    if (x < 25) {
      EXPECT_TRUE(grid.Blocked(GridIndex{x, 38})) << x;  // Nearer the wall than the robot.
    }
  }
  const TraversalGrid before = BuildTraversalGrid(map, config);
  TraversalGrid free_robot = before;
  FreeWayOut(free_robot, map, {20, 10}, config);
  EXPECT_TRUE(DiffGrids(before, free_robot).empty());
}

}  // namespace
}  // namespace dynamap::planning
