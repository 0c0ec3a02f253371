#include "dynamap/planning/FloorGaps.hpp"

#include <gtest/gtest.h>

namespace dynamap::planning {
namespace {

constexpr double kRes = 0.05;

int Count(const GridMap& map, CellState state) {
  int n = 0;
  for (const CellState s : map.cells) n += s == state ? 1 : 0;
  return n;
}

// A 2 x 2 m floor patch in the middle of an unknown 4 x 4 m grid.
GridMap Patch() {
  GridMap map(80, 80, kRes);
  for (int y = 20; y < 60; ++y) {
    for (int x = 20; x < 60; ++x) map.Set({x, y}, CellState::kNavigable);
  }
  return map;
}

TEST(CloseFloorGaps, FillsGrazingRayStripesInsideSeenFloor) {
  GridMap map = Patch();
  for (int y = 22; y < 58; y += 4) {
    for (int x = 20; x < 60; ++x) map.Set({x, y}, CellState::kUnknown);  // 1-cell stripes.
  }
  for (int x = 30; x < 60; x += 3) map.Set({x, 41}, CellState::kUnknown);  // Speckles.
  const GridMap clean = Patch();
  EXPECT_GT(CloseFloorGaps(map, 0.15), 0);
  EXPECT_EQ(map.cells, clean.cells);
}

TEST(CloseFloorGaps, TheSeenFloorsOuterEdgeDoesNotGrow) {
  GridMap map = Patch();
  EXPECT_EQ(CloseFloorGaps(map, 0.2), 0);
  EXPECT_EQ(Count(map, CellState::kNavigable), 40 * 40);
}

TEST(CloseFloorGaps, KeepsObstaclesHolesAndGapsWiderThanAsked) {
  GridMap map = Patch();
  for (int y = 20; y < 60; ++y) {
    map.Set({30, y}, CellState::kObstacle);  // A wall across the floor.
    map.Set({40, y}, CellState::kHole);      // A one-cell trench.
    for (int x = 48; x < 54; ++x) map.Set({x, y}, CellState::kUnknown);  // 0.3 m unseen.
  }
  EXPECT_EQ(CloseFloorGaps(map, 0.15), 0);
  EXPECT_EQ(Count(map, CellState::kObstacle), 40);
  EXPECT_EQ(Count(map, CellState::kHole), 40);
  EXPECT_EQ(map.At({50, 30}), CellState::kUnknown);
}

TEST(CloseFloorGaps, NothingToDoForAZeroGap) {
  GridMap map = Patch();
  map.Set({30, 30}, CellState::kUnknown);
  EXPECT_EQ(CloseFloorGaps(map, 0.0), 0);
  EXPECT_EQ(map.At({30, 30}), CellState::kUnknown);
}

TEST(CloseWallGaps, ClosesMissedCellsInAWallButNotADoorway) {
  GridMap map(40, 20, 0.05, CellState::kNavigable);
  for (int x = 0; x < 40; ++x) map.Set({x, 10}, CellState::kObstacle);
  for (int x = 0; x < 40; ++x) map.Set({x, 11}, CellState::kUnknown);  // Behind the wall.
  map.Set({5, 10}, CellState::kUnknown);                                 // Missed cells.
  map.Set({6, 10}, CellState::kUnknown);
  for (int x = 20; x < 38; ++x) map.Set({x, 10}, CellState::kUnknown);   // A 0.9 m doorway.
  EXPECT_EQ(CloseWallGaps(map, 0.15), 2);
  EXPECT_EQ(map.At({5, 10}), CellState::kObstacle);
  EXPECT_EQ(map.At({6, 10}), CellState::kObstacle);
  EXPECT_EQ(map.At({28, 10}), CellState::kUnknown);
}

TEST(AssumeFloorAround, StopsAtWallsAndHoles) {
  // The robot 0.3 m from a wall; beyond the wall unknown space must stay unknown.
  GridMap map(40, 40, 0.05, CellState::kUnknown);
  for (int y = 0; y < 40; ++y) map.Set({26, y}, CellState::kObstacle);
  map.Set({15, 20}, CellState::kHole);
  const int filled = AssumeFloorAround(map, 1.0, 1.0, 0.5);  // Cell (20, 20).
  EXPECT_GT(filled, 0);
  EXPECT_EQ(map.At({20, 20}), CellState::kNavigable);
  EXPECT_EQ(map.At({25, 20}), CellState::kNavigable);
  EXPECT_EQ(map.At({27, 20}), CellState::kUnknown);  // Behind the wall, although within 0.5 m.
  EXPECT_EQ(map.At({15, 20}), CellState::kHole);
  EXPECT_EQ(map.At({20, 31}), CellState::kUnknown);  // Beyond the radius.
}

TEST(ExtendHolesIntoUnknown, UnseenCellsAtAStairPitsEdgeBecomeHole) {
  GridMap map(40, 40, kRes, CellState::kNavigable);
  for (int y = 10; y < 30; ++y) {
    for (int x = 20; x < 30; ++x) map.Set({x, y}, CellState::kHole);
  }
  for (int y = 30; y < 40; ++y) {
    for (int x = 15; x < 35; ++x) map.Set({x, y}, CellState::kUnknown);  // Edge not seen.
  }
  map.Set({5, 5}, CellState::kUnknown);  // Unknown far from the pit stays unknown.
  EXPECT_GT(ExtendHolesIntoUnknown(map, 0.36), 0);
  EXPECT_EQ(map.At({25, 30}), CellState::kHole);  // Next to the pit.
  EXPECT_EQ(map.At({25, 36}), CellState::kHole);  // 7 cells = 0.35 m from it.
  EXPECT_EQ(map.At({25, 38}), CellState::kUnknown);  // 0.45 m: beyond the radius.
  EXPECT_EQ(map.At({5, 5}), CellState::kUnknown);
  EXPECT_EQ(map.At({19, 20}), CellState::kNavigable);  // Seen floor is never changed.
}

}  // namespace
}  // namespace dynamap::planning
