#include "dynamap/planning/Visibility.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace dynamap::planning {

std::vector<int> VisibleCells(const GridMap& map, GridIndex from, const ViewCone& cone) {
  std::vector<int> seen;
  if (!map.Contains(from) || cone.rays <= 0) return seen;
  const double range = cone.range_m / map.resolution_m;
  const double min_range = cone.min_range_m / map.resolution_m;
  const bool full_circle = cone.fov_rad >= 2.0 * M_PI - 1e-9;
  const int rays = cone.rays;
  const double step_angle = full_circle ? 2.0 * M_PI / rays : cone.fov_rad / std::max(1, rays - 1);
  const double first = full_circle ? 0.0 : cone.heading_rad - 0.5 * cone.fov_rad;
  // Half-cell steps from the cell centre: simple and dense enough at sensor ranges of a few
  // metres (the ray spacing, not the step, limits what a far ray misses).
  // Deduplicate with a bitmap over the cone's bounding square rather than sorting: rays
  // revisit cells at every half step and overlap near the origin.
  const int r = static_cast<int>(std::ceil(range)) + 1;
  const int side = 2 * r + 1;
  std::vector<std::uint8_t> marked(static_cast<std::size_t>(side) * side, 0);
  for (int i = 0; i < rays; ++i) {
    const double a = first + i * step_angle;
    const double dx = std::cos(a) * 0.5;
    const double dy = std::sin(a) * 0.5;
    double x = from.x + 0.5;
    double y = from.y + 0.5;
    for (double t = 0.0; t <= range; t += 0.5) {
      const GridIndex c{static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y))};
      if (!map.Contains(c)) break;
      std::uint8_t& m = marked[static_cast<std::size_t>(c.y - from.y + r) * side + (c.x - from.x + r)];
      if (m == 0 && t >= min_range) {
        m = 1;
        seen.push_back(map.Index(c));
      }
      if (map.At(c) == CellState::kObstacle) break;
      x += dx;
      y += dy;
    }
  }
  return seen;
}

}  // namespace dynamap::planning
