// Waiting for people in the way: a room whose only door a person stands in.
#include "dynamap/planning/BlockedWay.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynamap/planning/AStar.hpp"
#include "dynamap/planning/CostField.hpp"

namespace dynamap::planning {
namespace {

constexpr double kRes = 0.05;

// 6 x 3 m of floor, a wall at x = 3 m with a 1 m doorway (y from 1 to 2 m).
GridMap TwoRooms() {
  GridMap grid(120, 60, kRes, CellState::kNavigable);
  for (int y = 0; y < 60; ++y) {
    if (y < 20 || y >= 40) grid.Set({60, y}, CellState::kObstacle);
  }
  return grid;
}

// A person of 0.4 m in the doorway, as the indices the projection reports.
std::vector<int> PersonInTheDoorway(GridMap& grid) {
  std::vector<int> cells;
  for (int y = 26; y < 34; ++y) {
    for (int x = 57; x < 65; ++x) {
      const int i = grid.Index({x, y});
      grid.Set({x, y}, CellState::kObstacle);
      cells.push_back(i);
    }
  }
  return cells;
}

// What the planner judges the way on: the two rooms as if the person were not there.
TraversalGrid WithoutThePerson() {
  GridMap grid = TwoRooms();
  const std::vector<int> person = PersonInTheDoorway(grid);
  return BuildTraversalGrid(WithoutDynamicObstacles(grid, person), {});
}

const GridIndex kRobot{20, 30};
const GridIndex kGoal{100, 30};

TEST(BlockedWay, WaitsForAPersonInTheDoorLookingThatWayThenGivesUp) {
  GridMap grid = TwoRooms();
  (void)PersonInTheDoorway(grid);
  ASSERT_FALSE(AStarSearch(BuildTraversalGrid(grid, {}), kRobot, kGoal).found);
  const TraversalGrid passable = WithoutThePerson();

  BlockedWay way(BlockedWayConfig{10.0, 1.0});
  const BlockedWayVerdict first = way.Judge(&passable, kRobot, kGoal, kRes, 100.0);
  ASSERT_TRUE(first.wait);
  // It looks a metre down the way through the door.
  EXPECT_NEAR(std::hypot(first.look_at.x - kRobot.x, first.look_at.y - kRobot.y) * kRes, 1.0, 0.1);
  EXPECT_GT(first.look_at.x, kRobot.x);
  const BlockedWayVerdict later = way.Judge(&passable, kRobot, kGoal, kRes, 109.5);
  EXPECT_TRUE(later.wait);
  EXPECT_DOUBLE_EQ(later.blocked_for_s, 9.5);
  EXPECT_FALSE(way.Judge(&passable, kRobot, kGoal, kRes, 110.0).wait);
}

TEST(BlockedWay, AWallIsNotWaitedFor) {
  GridMap grid = TwoRooms();
  const std::vector<int> person = PersonInTheDoorway(grid);
  // The door itself is shut (static): the way stays blocked without the person too.
  for (int y = 20; y < 40; ++y) grid.Set({66, y}, CellState::kObstacle);
  const TraversalGrid passable = BuildTraversalGrid(WithoutDynamicObstacles(grid, person), {});
  BlockedWay way;
  EXPECT_FALSE(way.Judge(&passable, kRobot, kGoal, kRes, 100.0).wait);
  EXPECT_FALSE(way.Judge(nullptr, kRobot, kGoal, kRes, 100.0).wait);  // No people at all.
}

TEST(BlockedWay, AFoundPathStartsTheNextWaitAfresh) {
  const TraversalGrid passable = WithoutThePerson();
  BlockedWay way(BlockedWayConfig{10.0, 1.0});
  ASSERT_TRUE(way.Judge(&passable, kRobot, kGoal, kRes, 100.0).wait);
  way.Clear();
  const BlockedWayVerdict again = way.Judge(&passable, kRobot, kGoal, kRes, 108.0);
  EXPECT_TRUE(again.wait);
  EXPECT_DOUBLE_EQ(again.blocked_for_s, 0.0);
  EXPECT_TRUE(way.Judge(&passable, kRobot, kGoal, kRes, 117.0).wait);
}

TEST(BlockedWay, OnlyObstaclesOfTheDynamicMapAreCleared) {
  GridMap grid = TwoRooms();
  const std::vector<int> person = PersonInTheDoorway(grid);
  std::vector<int> listed = person;
  grid.Set({10, 10}, CellState::kUnknown);
  listed.push_back(grid.Index({10, 10}));  // Unknown stays unknown.
  const GridMap cleared = WithoutDynamicObstacles(grid, listed);
  for (const int i : person) EXPECT_EQ(cleared.cells[static_cast<std::size_t>(i)], CellState::kNavigable);
  EXPECT_EQ(cleared.At({10, 10}), CellState::kUnknown);
  EXPECT_EQ(cleared.At({60, 10}), CellState::kObstacle);  // The wall is not listed.
}

}  // namespace
}  // namespace dynamap::planning
