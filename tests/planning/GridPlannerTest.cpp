// D* Lite against A* on changing grids, the move rules, the cost field and path shortening.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "dynamap/planning/AStar.hpp"
#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/DStarLite.hpp"
#include "dynamap/planning/PathPlanner.hpp"
#include "dynamap/planning/PathShortening.hpp"

namespace dynamap::planning {
namespace {

TraversalGrid FromRows(const std::vector<std::string>& rows) {
  TraversalGrid grid(static_cast<int>(rows[0].size()), static_cast<int>(rows.size()));
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (rows[y][x] == '#') grid.penalty[grid.Index({x, y})] = kInfinity;
    }
  }
  return grid;
}

void ExpectSameCost(const GridPath& a, const GridPath& b, const std::string& where) {
  ASSERT_EQ(a.found, b.found) << where;
  if (a.found) {
    EXPECT_NEAR(a.cost, b.cost, 1e-9 * std::max(1.0, b.cost)) << where;
  }
}

TEST(GridPlanners, DiagonalMayNotCutACorner) {
  const TraversalGrid grid = FromRows({"..", "#."});
  // (0,0) → (1,1) diagonally would cut the blocked (0,1): it has to go round via (1,0).
  const GridPath astar = AStarSearch(grid, {0, 0}, {1, 1});
  ASSERT_TRUE(astar.found);
  EXPECT_DOUBLE_EQ(astar.cost, 2.0);
  DStarLite dstar(grid, {0, 0}, {1, 1});
  EXPECT_DOUBLE_EQ(dstar.Plan().cost, 2.0);
}

TEST(GridPlanners, UnreachableGoalIsNotFound) {
  const TraversalGrid grid = FromRows({"..#..", "..#..", "..#.."});
  EXPECT_FALSE(AStarSearch(grid, {0, 0}, {4, 2}).found);
  DStarLite dstar(grid, {0, 0}, {4, 2});
  EXPECT_FALSE(dstar.Plan().found);
}

TEST(GridPlanners, TheRobotsOwnBlockedCellDoesNotWallItIn) {
  TraversalGrid grid = FromRows({"....", ".#..", "...."});
  EXPECT_FALSE(AStarSearch(grid, {1, 1}, {3, 1}).found);  // Inflation drawn over the robot.
  FreeStandingCell(grid, {1, 1});
  const GridPath out = AStarSearch(grid, {1, 1}, {3, 1});
  ASSERT_TRUE(out.found);
  EXPECT_DOUBLE_EQ(out.cost, 1.0 + 0.5 * kStandingCellPenalty + 1.0);  // Left at once.
  FreeStandingCell(grid, {7, 7});  // Off the grid: nothing happens.
  EXPECT_EQ(grid.penalty[grid.Index({1, 1})], kStandingCellPenalty);
}

TEST(GridPlanners, ProximityPenaltyMakesThePathDetour) {
  TraversalGrid grid(9, 3);
  // A costly middle row: the straight line is 8 long but costs 8·(1+5) = 48.
  for (int x = 1; x < 8; ++x) grid.penalty[grid.Index({x, 1})] = 5.0;
  const GridPath path = AStarSearch(grid, {0, 1}, {8, 1});
  ASSERT_TRUE(path.found);
  EXPECT_LT(path.cost, 48.0);
  DStarLite dstar(grid, {0, 1}, {8, 1});
  ExpectSameCost(dstar.Plan(), path, "penalty");
}

TEST(GridPlanners, DStarLiteRepairsAfterADoorCloses) {
  TraversalGrid grid = FromRows({"....#....", "....#....", ".........", "....#....",
                                 "....#....", "....#....", "....#...."});
  DStarLite dstar(grid, {0, 0}, {8, 0});
  ASSERT_TRUE(dstar.Plan().found);
  dstar.UpdateCells({{grid.Index({4, 2}), kInfinity}});
  EXPECT_FALSE(dstar.Plan().found);
  dstar.UpdateCells({{grid.Index({4, 6}), 0.0}});
  const GridPath reopened = dstar.Plan();
  ASSERT_TRUE(reopened.found);
  grid.penalty[grid.Index({4, 2})] = kInfinity;
  grid.penalty[grid.Index({4, 6})] = 0.0;
  ExpectSameCost(reopened, AStarSearch(grid, {0, 0}, {8, 0}), "reopened");
}

// Property: after any batch of cell changes and robot moves, D* Lite's repaired result
// costs exactly what A* finds from scratch on the changed grid.
TEST(GridPlanners, DStarLiteMatchesAStarAfterRandomChangesAndMoves) {
  constexpr int kSeeds = 500;
  constexpr int kRounds = 12;
  int compared_found = 0;
  for (int seed = 0; seed < kSeeds; ++seed) {
    std::mt19937 rng(static_cast<unsigned>(seed));
    const int width = 20 + seed % 25;
    const int height = 15 + seed % 20;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    TraversalGrid grid(width, height);
    const double density = 0.1 + 0.25 * unit(rng);
    for (double& p : grid.penalty) {
      const double r = unit(rng);
      p = r < density ? kInfinity : (r < density + 0.2 ? 3.0 * unit(rng) : 0.0);
    }
    std::uniform_int_distribution<int> rx(0, width - 1);
    std::uniform_int_distribution<int> ry(0, height - 1);
    GridIndex start{rx(rng), ry(rng)};
    const GridIndex goal{rx(rng), ry(rng)};
    grid.penalty[grid.Index(start)] = 0.0;
    grid.penalty[grid.Index(goal)] = 0.0;
    DStarLite dstar(grid, start, goal);
    for (int round = 0; round < kRounds; ++round) {
      const std::string where = "seed " + std::to_string(seed) + " round " + std::to_string(round);
      const GridPath path = dstar.Plan();
      const GridPath reference = AStarSearch(grid, start, goal);
      ExpectSameCost(path, reference, where);
      if (path.found) {
        ++compared_found;
        EXPECT_DOUBLE_EQ(PathCost(grid, path.cells), path.cost) << where;
        // The robot drives a few cells along the path.
        const std::size_t steps = std::min<std::size_t>(path.cells.size() - 1, 1 + rng() % 4);
        start = path.cells[steps];
      } else if (unit(rng) < 0.5) {
        start = {rx(rng), ry(rng)};  // Relocalised elsewhere (a jump, not a drive).
      }
      dstar.MoveStart(start);
      // A batch of changes, half of them near the robot, where repairs are hardest.
      std::vector<CellChange> changes;
      const int batch = 1 + static_cast<int>(rng() % 12);
      for (int k = 0; k < batch; ++k) {
        GridIndex c{rx(rng), ry(rng)};
        if (k % 2 == 0) {
          c = {std::clamp(start.x + static_cast<int>(rng() % 7) - 3, 0, width - 1),
               std::clamp(start.y + static_cast<int>(rng() % 7) - 3, 0, height - 1)};
        }
        const double r = unit(rng);
        const double value = r < 0.45 ? kInfinity : (r < 0.7 ? 0.0 : 4.0 * unit(rng));
        if (c == goal || c == start) continue;
        grid.penalty[grid.Index(c)] = value;
        changes.push_back({grid.Index(c), value});
      }
      dstar.UpdateCells(changes);
    }
  }
  EXPECT_GT(compared_found, kSeeds * kRounds / 3);  // The property was exercised, not vacuous.
}

TEST(PathPlanner, IncrementalAndFromScratchModesAgreeAsTheMapAndRobotChange) {
  GridMap map(60, 40, 0.1, CellState::kNavigable);
  CostFieldConfig cost;
  cost.robot_radius_m = 0.2;
  TraversalGrid grid = BuildTraversalGrid(map, cost);
  PathPlanner dstar("dstar", grid);
  PathPlanner astar("astar", grid);
  EXPECT_FALSE(dstar.Plan().found);  // No goal yet.
  for (PathPlanner* p : {&dstar, &astar}) {
    p->MoveStart({2, 20});
    p->SetGoal({57, 20});
  }
  std::mt19937 rng(7);
  for (int step = 0; step < 20; ++step) {
    // A wall segment appears somewhere; the robot advances along its path.
    const int x = 10 + static_cast<int>(rng() % 40);
    const int y = static_cast<int>(rng() % 30);
    for (int k = 0; k < 8; ++k) map.Set({x, y + k}, CellState::kObstacle);
    grid = BuildTraversalGrid(map, cost);
    dstar.SetGrid(grid);
    astar.SetGrid(grid);
    const GridPath a = astar.Plan();
    const GridPath d = dstar.Plan();
    ExpectSameCost(d, a, "step " + std::to_string(step));
    if (!d.found || d.cells.size() < 3) break;
    dstar.MoveStart(d.cells[2]);
    astar.MoveStart(d.cells[2]);
  }
}

TEST(CostField, InflatesObstaclesByTheRobotRadius) {
  GridMap map(21, 21, 0.1, CellState::kNavigable);
  map.Set({10, 10}, CellState::kObstacle);
  CostFieldConfig config;
  config.robot_radius_m = 0.3;
  config.proximity_range_m = 0.3;
  config.proximity_weight = 2.0;
  const TraversalGrid grid = BuildTraversalGrid(map, config);
  EXPECT_TRUE(grid.Blocked(GridIndex{10, 10}));
  EXPECT_TRUE(grid.Blocked(GridIndex{12, 10}));   // 0.2 m away.
  EXPECT_FALSE(grid.Blocked(GridIndex{13, 10}));  // 0.3 m: on the boundary.
  EXPECT_NEAR(grid.penalty[grid.Index({13, 10})], 2.0, 1e-6);
  EXPECT_NEAR(grid.penalty[grid.Index({16, 10})], 0.0, 1e-6);
  EXPECT_GT(grid.penalty[grid.Index({14, 10})], grid.penalty[grid.Index({15, 10})]);
}

TEST(CostField, ClearanceFollowsTheDistanceToTheInflatedBoundary) {
  GridMap map(31, 1, 0.1, CellState::kNavigable);
  map.Set({0, 0}, CellState::kObstacle);
  CostFieldConfig config;
  config.robot_radius_m = 0.3;
  config.proximity_range_m = 1.0;
  const TraversalGrid grid = BuildTraversalGrid(map, config);
  EXPECT_DOUBLE_EQ(Clearance(grid, {2, 0}, config), 0.0);   // Inside the radius: blocked.
  EXPECT_NEAR(Clearance(grid, {8, 0}, config), 0.5, 1e-6);  // 0.8 m from the obstacle.
  EXPECT_NEAR(Clearance(grid, {25, 0}, config), 1.0, 1e-6);  // Beyond the range: at least.
}

TEST(CostField, UnknownBlocksUnlessConfiguredOptimistic) {
  GridMap map(5, 1, 0.1, CellState::kNavigable);
  map.Set({4, 0}, CellState::kUnknown);
  map.Set({0, 0}, CellState::kHole);
  CostFieldConfig config;
  config.robot_radius_m = 0.0;
  config.proximity_range_m = 0.0;
  EXPECT_TRUE(BuildTraversalGrid(map, config).Blocked(GridIndex{4, 0}));
  EXPECT_TRUE(BuildTraversalGrid(map, config).Blocked(GridIndex{0, 0}));
  config.unknown_is_obstacle = false;
  EXPECT_FALSE(BuildTraversalGrid(map, config).Blocked(GridIndex{4, 0}));
}

TEST(PathShortening, KeepsOnlyCornersOfAnLShapedCorridor) {
  const TraversalGrid grid = FromRows({"......", "#####.", "#####.", "#####."});
  const GridPath path = AStarSearch(grid, {0, 0}, {5, 3});
  ASSERT_TRUE(path.found);
  const std::vector<GridIndex> shortened = ShortenPath(grid, path.cells);
  EXPECT_EQ(shortened, (std::vector<GridIndex>{{0, 0}, {5, 0}, {5, 3}}));
}

TEST(PathShortening, LineOfSightRespectsCorners) {
  const TraversalGrid grid = FromRows({"..", "#."});
  EXPECT_FALSE(LineOfSight(grid, {0, 0}, {1, 1}));
  EXPECT_TRUE(LineOfSight(grid, {0, 0}, {1, 0}));
  const TraversalGrid open = FromRows({"....", "...."});
  EXPECT_TRUE(LineOfSight(open, {0, 0}, {3, 1}));
}

}  // namespace
}  // namespace dynamap::planning
