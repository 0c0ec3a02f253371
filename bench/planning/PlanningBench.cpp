// D* Lite repairs versus A* from scratch after local changes on a 500 x 500 office grid
// (a door closing, a person stepping onto the path, at several distances along the path),
// one target-planning decision on an office-sized, partly explored map, and the control
// step's path shift at a doorway seen 0.12 m off the map (its costliest case).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "dynamap/planning/AStar.hpp"
#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/DStarLite.hpp"
#include "dynamap/planning/PathShift.hpp"
#include "dynamap/planning/SurfaceCoverage.hpp"
#include "dynamap/planning/TargetPlanner.hpp"

namespace dynamap::planning {
namespace {

constexpr double kRes = 0.05;
constexpr int kSize = 500;  // 25 x 25 m.
constexpr int kWalls[] = {100, 200, 300, 400};
constexpr int kDoorY[] = {120, 380};
constexpr int kDoorHalfWidth = 12;  // 1.25 m doors.

void Fill(GridMap* map, int x0, int y0, int x1, int y1, CellState s) {
  for (int y = std::max(0, y0); y <= std::min(map->height - 1, y1); ++y) {
    for (int x = std::max(0, x0); x <= std::min(map->width - 1, x1); ++x) map->Set({x, y}, s);
  }
}

// Five halls in a row separated by walls with two doors each, some furniture.
GridMap Office() {
  GridMap map(kSize, kSize, kRes, CellState::kNavigable);
  Fill(&map, 0, 0, kSize - 1, 1, CellState::kObstacle);
  Fill(&map, 0, kSize - 2, kSize - 1, kSize - 1, CellState::kObstacle);
  Fill(&map, 0, 0, 1, kSize - 1, CellState::kObstacle);
  Fill(&map, kSize - 2, 0, kSize - 1, kSize - 1, CellState::kObstacle);
  for (const int x : kWalls) {
    Fill(&map, x - 1, 0, x + 1, kSize - 1, CellState::kObstacle);
    for (const int y : kDoorY) Fill(&map, x - 1, y - kDoorHalfWidth, x + 1, y + kDoorHalfWidth, CellState::kNavigable);
  }
  for (int i = 0; i < 5; ++i) {
    const int x0 = 30 + i * 100;
    Fill(&map, x0, 200, x0 + 30, 230, CellState::kObstacle);  // Desks.
    Fill(&map, x0 + 20, 300, x0 + 50, 310, CellState::kObstacle);
  }
  return map;
}

const GridIndex kStart{30, 250};
const GridIndex kGoal{470, 250};

struct Scenario {
  TraversalGrid base;
  TraversalGrid changed;
  std::vector<CellChange> forward;   // base → changed.
  std::vector<CellChange> backward;  // changed → base.
};

// kind 0: a person (0.3 m radius) steps onto the path at `percent` of its length from the
// robot; kind 1: the door the path uses in wall `percent` / 25 (1..4) closes.
Scenario MakeScenario(int kind, int percent) {
  const GridMap office = Office();
  const CostFieldConfig cost;
  Scenario s;
  s.base = BuildTraversalGrid(office, cost);
  const GridPath path = AStarSearch(s.base, kStart, kGoal);
  GridMap changed = office;
  if (kind == 0) {
    const GridIndex c = path.cells[path.cells.size() * percent / 100];
    const int r = static_cast<int>(std::ceil(0.3 / kRes));
    for (int dy = -r; dy <= r; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        if (dx * dx + dy * dy <= r * r) changed.Set({c.x + dx, c.y + dy}, CellState::kObstacle);
      }
    }
  } else {
    const int wall = kWalls[std::clamp(percent / 25, 1, 4) - 1];
    for (const GridIndex& c : path.cells) {
      if (c.x != wall) continue;
      const int door = std::abs(c.y - kDoorY[0]) < std::abs(c.y - kDoorY[1]) ? kDoorY[0] : kDoorY[1];
      Fill(&changed, wall - 1, door - kDoorHalfWidth, wall + 1, door + kDoorHalfWidth, CellState::kObstacle);
      break;
    }
  }
  s.changed = BuildTraversalGrid(changed, cost);
  s.forward = DiffGrids(s.base, s.changed);
  s.backward = DiffGrids(s.changed, s.base);
  return s;
}

void BM_DStarLiteReplan(benchmark::State& state) {
  const Scenario s = MakeScenario(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  DStarLite dstar(s.base, kStart, kGoal);
  benchmark::DoNotOptimize(dstar.Plan());
  long expansions = 0;
  long replans = 0;
  for (auto _ : state) {
    dstar.UpdateCells(s.forward);
    const GridPath path = dstar.Plan();
    benchmark::DoNotOptimize(path.cost);
    expansions += path.expansions;
    ++replans;
    state.PauseTiming();  // Undo the change (not measured): the next repair starts alike.
    dstar.UpdateCells(s.backward);
    benchmark::DoNotOptimize(dstar.Plan());
    state.ResumeTiming();
  }
  state.counters["expansions"] = static_cast<double>(expansions) / static_cast<double>(replans);
  state.counters["changed_cells"] = static_cast<double>(s.forward.size());
}

void BM_AStarFromScratch(benchmark::State& state) {
  const Scenario s = MakeScenario(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  long expansions = 0;
  long plans = 0;
  for (auto _ : state) {
    const GridPath path = AStarSearch(s.changed, kStart, kGoal);
    benchmark::DoNotOptimize(path.cost);
    expansions += path.expansions;
    ++plans;
  }
  state.counters["expansions"] = static_cast<double>(expansions) / static_cast<double>(plans);
}

void BM_DStarLiteFromScratch(benchmark::State& state) {
  const TraversalGrid grid = BuildTraversalGrid(Office(), CostFieldConfig{});
  long expansions = 0;
  long plans = 0;
  for (auto _ : state) {
    DStarLite dstar(grid, kStart, kGoal);
    const GridPath path = dstar.Plan();
    benchmark::DoNotOptimize(path.cost);
    expansions += path.expansions;
    ++plans;
  }
  state.counters["expansions"] = static_cast<double>(expansions) / static_cast<double>(plans);
}

void BM_CostFieldRebuild(benchmark::State& state) {
  const GridMap office = Office();
  for (auto _ : state) benchmark::DoNotOptimize(BuildTraversalGrid(office, CostFieldConfig{}));
}

// Person at 10..90 % of the path from the robot; doors of walls 1..4 (25..100 → wall).
void ChangeArgs(benchmark::internal::Benchmark* b) {
  for (const int p : {5, 10, 25, 50, 75, 90}) b->Args({0, p});
  for (const int w : {25, 50, 75, 100}) b->Args({1, w});
}

BENCHMARK(BM_DStarLiteReplan)->Apply(ChangeArgs)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AStarFromScratch)->Apply(ChangeArgs)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_DStarLiteFromScratch)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CostFieldRebuild)->Unit(benchmark::kMillisecond);

// Office floor like resources/worlds/office.yaml (30 x 16 m at 5 cm): corridor with rooms
// north and south, explored around the robot's first stops, the rest unknown.
GridMap PartlyExploredOffice() {
  GridMap truth(600, 320, kRes, CellState::kNavigable);
  Fill(&truth, 0, 0, 599, 3, CellState::kObstacle);
  Fill(&truth, 0, 316, 599, 319, CellState::kObstacle);
  Fill(&truth, 0, 0, 3, 319, CellState::kObstacle);
  Fill(&truth, 596, 0, 599, 319, CellState::kObstacle);
  Fill(&truth, 0, 139, 599, 141, CellState::kObstacle);  // Corridor walls at y = 7 m, 9 m.
  Fill(&truth, 0, 179, 599, 181, CellState::kObstacle);
  for (int x = 120; x < 600; x += 120) {
    Fill(&truth, x, 0, x + 2, 139, CellState::kObstacle);
    Fill(&truth, x + 60, 181, x + 62, 319, CellState::kObstacle);
  }
  for (int x = 40; x < 600; x += 120) {
    Fill(&truth, x, 139, x + 18, 141, CellState::kNavigable);  // Doors.
    Fill(&truth, x + 30, 179, x + 48, 181, CellState::kNavigable);
    Fill(&truth, x + 10, 40, x + 50, 70, CellState::kObstacle);  // Desks.
    Fill(&truth, x + 20, 230, x + 60, 260, CellState::kObstacle);
  }
  GridMap map = truth;
  const GridIndex stops[] = {{30, 160}, {150, 160}, {270, 160}, {60, 90}, {80, 240}};
  for (int i = 0; i < static_cast<int>(map.cells.size()); ++i) {
    const GridIndex c = map.Cell(i);
    bool known = false;
    for (const GridIndex& s : stops) {
      known = known || (c.x - s.x) * (c.x - s.x) + (c.y - s.y) * (c.y - s.y) < 90 * 90;
    }
    if (!known) map.cells[i] = CellState::kUnknown;
  }
  return map;
}

void BM_TargetPlanning(benchmark::State& state) {
  const GridMap map = PartlyExploredOffice();
  const TraversalGrid grid = BuildTraversalGrid(map, CostFieldConfig{});
  TargetPlannerConfig config;
  config.strategy = std::array<const char*, 3>{"gain", "nearest-frontier", "tour"}.at(
      static_cast<std::size_t>(state.range(0)));
  const TargetPlanner planner(config, kRes);
  SurfaceCoverage coverage;
  coverage.Observe(map, {1.5, 8.0, 0.0});
  int candidates = 0;
  for (auto _ : state) {
    const TargetDecision d = planner.Plan(map, grid, {30, 160}, {30, 160}, &coverage, 0.0);
    candidates = static_cast<int>(d.candidates.size());
    benchmark::DoNotOptimize(d.cell);
  }
  state.counters["candidates"] = candidates;
}
BENCHMARK(BM_TargetPlanning)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond);

// What the obstacle memory holds around a doorway: a 0.12 m wall along y = 0 with a 0.9 m
// doorway centred 0.12 m east of the path, in 5 cm cells (both faces and the posts), plus a
// desk's edge 0.5 m west of the path beyond the door. The path runs south through it; the
// robot is 0.6 m before the wall, so the whole shift search runs (the unshifted stretch is
// within the comfort distance of the posts).
void BM_PathShiftAtADoorway(benchmark::State& state) {
  std::vector<Eigen::Vector2d> seen;
  for (double x = -2.5; x <= 2.5; x += 0.05) {
    if (std::abs(x - 0.12) < 0.45) continue;
    seen.emplace_back(x, 0.06);
    seen.emplace_back(x, -0.06);
  }
  for (double y = -1.5; y <= -0.5; y += 0.05) seen.emplace_back(-0.5, y);
  const std::vector<Eigen::Vector2d> path = {{0.0, 2.0}, {0.0, -2.0}};
  const double footprint = 0.36;
  Eigen::Vector2d shift;
  for (auto _ : state) {
    shift = PathShiftTarget(path, {0.0, 0.6}, seen, footprint, {});
    benchmark::DoNotOptimize(shift);
  }
  state.counters["points"] = static_cast<double>(seen.size());
  state.counters["shift_mm"] = 1e3 * shift.x();
}
BENCHMARK(BM_PathShiftAtADoorway)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace dynamap::planning

BENCHMARK_MAIN();
