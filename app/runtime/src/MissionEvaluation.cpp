#include "dynamap/app/runtime/MissionEvaluation.hpp"

#include <cmath>
#include <algorithm>
#include <deque>

#include "dynamap/robotio/sim/CollisionWorld.hpp"

namespace dynamap::app::runtime {

using planning::CellState;
using planning::GridIndex;

TruthGrid BuildTruthGrid(const robotio::sim::World& world, planning::GridMap area,
                         double footprint_radius_m, double robot_height_m, double t_s) {
  const robotio::sim::CollisionWorld collisions(world, robot_height_m);
  TruthGrid truth{std::move(area)};
  planning::GridMap& grid = truth.reachable;
  // Only the extent of `area` is used: whatever states it holds are not truth.
  std::fill(grid.cells.begin(), grid.cells.end(), CellState::kUnknown);
  std::vector<std::uint8_t> standable(grid.cells.size(), 0);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const robotio::Pose2D w = world.ToWorld({grid.CenterX(x), grid.CenterY(y), 0.0});
      const Eigen::Vector2d c(w.x, w.y);
      const int index = grid.Index({x, y});
      const bool on_floor = (c.array() >= world.floor_min.array()).all() &&
                            (c.array() <= world.floor_max.array()).all();
      if (!on_floor || collisions.Check(c, 0.5 * grid.resolution_m, t_s).clearance_m < 0.0) {
        grid.cells[index] = CellState::kObstacle;
        continue;
      }
      standable[index] = collisions.Check(c, footprint_radius_m, t_s).clearance_m > 0.0;
    }
  }
  // Flood fill from the start (the map origin), 8-connected.
  const GridIndex start = grid.CellAt(0.0, 0.0);
  if (!grid.Contains(start)) return truth;
  std::deque<GridIndex> queue{start};
  standable[grid.Index(start)] = 1;
  grid.Set(start, CellState::kNavigable);
  while (!queue.empty()) {
    const GridIndex c = queue.front();
    queue.pop_front();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const GridIndex n{c.x + dx, c.y + dy};
        if (!grid.Contains(n) || !standable[grid.Index(n)] ||
            grid.At(n) == CellState::kNavigable) {
          continue;
        }
        grid.Set(n, CellState::kNavigable);
        queue.push_back(n);
      }
    }
  }
  return truth;
}

double ExploredFreeFraction(const TruthGrid& truth, const planning::GridMap& known) {
  const planning::GridMap& grid = truth.reachable;
  std::size_t reachable = 0;
  std::size_t known_free = 0;
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (grid.At({x, y}) != CellState::kNavigable) continue;
      ++reachable;
      const GridIndex k = known.CellAt(grid.CenterX(x), grid.CenterY(y));
      if (known.Contains(k) && known.At(k) == CellState::kNavigable) ++known_free;
    }
  }
  return reachable == 0 ? 0.0 : static_cast<double>(known_free) / static_cast<double>(reachable);
}

SurfaceCoverageResult SurfaceCoverage(
    const TruthGrid& truth, const robotio::PointList& samples, double robot_height_m,
    double inspection_distance_m, const std::function<bool(const Eigen::Vector3f&)>& inspected) {
  SurfaceCoverageResult result;
  const planning::GridMap& grid = truth.reachable;
  constexpr int kDirections = 24;
  // How far the sample's own solid may reach in the direction looked along: the sample
  // lies on its face, and a cell is solid when the solid comes within half a cell of its
  // centre, so an outward walk leaves it within 1.5 cells. Walls are 2 cells or thicker.
  constexpr double kOwnSolidCells = 1.5;
  for (const Eigen::Vector3f& s : samples) {
    if (s.z() < 0.2f || s.z() > robot_height_m) continue;  // Floor, and above the robot.
    bool can_be_seen = false;
    for (int d = 0; d < kDirections && !can_be_seen; ++d) {
      const double a = 2.0 * M_PI * d / kDirections;
      bool left_solid = false;
      for (double r = 0.0; r <= inspection_distance_m; r += 0.5 * grid.resolution_m) {
        const GridIndex c = grid.CellAt(s.x() + r * std::cos(a), s.y() + r * std::sin(a));
        if (!grid.Contains(c)) break;
        const CellState state = grid.At(c);
        if (state == CellState::kObstacle) {
          if (left_solid) break;  // Another solid in between: not from this side.
          // A surface faces this way only if its solid ends right there: a wall's outer
          // face, looked at through the wall from the room, is not visible.
          if (r > kOwnSolidCells * grid.resolution_m) break;
          continue;               // Still inside the sample's own wall or object.
        }
        left_solid = true;
        if (state == CellState::kNavigable) {
          can_be_seen = true;
          break;
        }
      }
    }
    if (!can_be_seen) continue;
    (inspected(s) ? result.inspected : result.missed).push_back(s);
  }
  return result;
}

}  // namespace dynamap::app::runtime
