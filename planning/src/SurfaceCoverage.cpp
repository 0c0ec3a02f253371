#include "dynamap/planning/SurfaceCoverage.hpp"

#include "dynamap/planning/Visibility.hpp"

namespace dynamap::planning {

void SurfaceCoverage::Observe(const GridMap& map, const robotio::Pose2D& pose) {
  inspected_.resize(map.cells.size(), 0);
  ViewCone cone;
  cone.range_m = config_.inspection_distance_m;
  cone.heading_rad = pose.theta;
  cone.fov_rad = config_.sensor_fov_rad;
  cone.rays = 120;
  for (const int i : VisibleCells(map, map.CellAt(pose.x, pose.y), cone)) {
    if (map.cells[i] == CellState::kObstacle) inspected_[i] = 1;
  }
}

bool SurfaceCoverage::InspectedNear(const GridMap& map, GridIndex c) const {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const GridIndex n{c.x + dx, c.y + dy};
      if (map.Contains(n) && Inspected(map.Index(n))) return true;
    }
  }
  return false;
}

bool SurfaceCoverage::IsSurface(const GridMap& map, GridIndex c) {
  if (!map.Contains(c) || map.At(c) != CellState::kObstacle) return false;
  const GridIndex around[4] = {{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}};
  for (const GridIndex& n : around) {
    if (map.Contains(n) && map.At(n) == CellState::kNavigable) return true;
  }
  return false;
}

double SurfaceCoverage::Fraction(const GridMap& map) const {
  int surfaces = 0;
  int seen = 0;
  for (int i = 0; i < static_cast<int>(map.cells.size()); ++i) {
    if (!IsSurface(map, map.Cell(i))) continue;
    ++surfaces;
    if (InspectedNear(map, map.Cell(i))) ++seen;
  }
  return surfaces == 0 ? 1.0 : static_cast<double>(seen) / surfaces;
}

}  // namespace dynamap::planning
