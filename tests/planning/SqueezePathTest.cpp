#include "dynamap/planning/SqueezePath.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynamap/planning/AStar.hpp"

namespace dynamap::planning {
namespace {

constexpr double kRes = 0.05;

// Two rooms joined by a doorway in a wall along y = 40: obstacle cells up to x = 30 and
// from x = 31 + `gap_cells`. Seed 4's office door: 14 free cells between obstacle cell
// centres 0.75 m apart, for a 0.72 m wide robot.
GridMap Doorway(int gap_cells) {
  GridMap map(80, 80, kRes, CellState::kNavigable);
  for (int x = 0; x < 80; ++x) {
    if (x <= 30 || x >= 31 + gap_cells) map.Set({x, 40}, CellState::kObstacle);
  }
  return map;
}

constexpr GridIndex kRobot{40, 20};
constexpr GridIndex kGoal{40, 60};

TEST(SqueezePath, GoesThroughADoorwayTheFullRadiusCloses) {
  const GridMap map = Doorway(14);
  const CostFieldConfig cost;
  ASSERT_FALSE(AStarSearch(BuildTraversalGrid(map, cost), kRobot, kGoal).found);
  const auto squeeze = FindSqueezePath(map, cost, kRobot, kGoal);
  ASSERT_TRUE(squeeze.has_value());
  EXPECT_EQ(squeeze->path.cells.front(), kRobot);
  EXPECT_EQ(squeeze->path.cells.back(), kGoal);
  // Through the middle of the doorway, at least the squeeze radius from both sides.
  for (const GridIndex& c : squeeze->path.cells) {
    if (c.y != 40) continue;
    EXPECT_GE((c.x - 30) * kRes, SqueezeRadius(cost, kRes) - 1e-9);
    EXPECT_GE((45 - c.x) * kRes, SqueezeRadius(cost, kRes) - 1e-9);
  }
}

TEST(SqueezePath, AGridAlreadyBuiltGivesTheSamePath) {
  // The planning worker builds the squeeze grid for target planning once per plan and
  // hands it over instead of inflating the map again.
  const GridMap map = Doorway(14);
  const CostFieldConfig cost;
  const auto from_map = FindSqueezePath(map, cost, kRobot, kGoal);
  const auto from_grid = FindSqueezePath(BuildSqueezeGrid(map, cost), kRobot, kGoal);
  ASSERT_TRUE(from_map.has_value());
  ASSERT_TRUE(from_grid.has_value());
  EXPECT_EQ(from_grid->path.cells, from_map->path.cells);
  EXPECT_EQ(from_grid->grid.penalty, from_map->grid.penalty);
}

TEST(SqueezePath, FindsNoWayThroughAGapNarrowerThanTheRobot) {
  // 0.65 m between obstacle cell centres: even touching both surfaces the robot does not fit.
  EXPECT_FALSE(FindSqueezePath(Doorway(12), CostFieldConfig{}, kRobot, kGoal).has_value());
  EXPECT_FALSE(FindSqueezePath(Doorway(0), CostFieldConfig{}, kRobot, kGoal).has_value());
}

TEST(SqueezePath, KeepsTheStairPitsWholeDistance) {
  // The same doorway with the wall's west side a pit: the robot that squeezes past a door
  // post keeps the full radius plus margin from a hole.
  GridMap map = Doorway(14);
  for (int x = 0; x <= 30; ++x) map.Set({x, 40}, CellState::kHole);
  const CostFieldConfig cost;
  EXPECT_FALSE(FindSqueezePath(map, cost, kRobot, kGoal).has_value());
  CostFieldConfig no_margin = cost;
  no_margin.hole_margin_m = 0.0;
  EXPECT_TRUE(FindSqueezePath(map, no_margin, kRobot, kGoal).has_value());
}

TEST(SqueezePath, StartsFromARobotStandingInsideTheInflatedZone) {
  // The robot stands in the doorway, 0.3 m from the west post: inside even the squeeze
  // radius, and still on its way.
  const auto squeeze = FindSqueezePath(Doorway(14), CostFieldConfig{}, {36, 40}, kGoal);
  ASSERT_TRUE(squeeze.has_value());
  EXPECT_EQ(squeeze->path.cells.front(), (GridIndex{36, 40}));
}

}  // namespace
}  // namespace dynamap::planning
