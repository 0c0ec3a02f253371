#include "dynamap/planning/DualMapView.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace dynamap::planning {

GridMap ProjectSavedMap(const mapping::DualOcTree& tree, const ProjectionConfig& config) {
  if (tree.getRoot() == nullptr) return GridMap();
  double min_x = 0.0, min_y = 0.0, min_z = 0.0, max_x = 0.0, max_y = 0.0, max_z = 0.0;
  tree.getMetricMin(min_x, min_y, min_z);
  tree.getMetricMax(max_x, max_y, max_z);
  const double resolution = tree.getResolution();
  GridMap area(static_cast<int>(std::ceil((max_x - min_x) / resolution)),
               static_cast<int>(std::ceil((max_y - min_y) / resolution)), resolution);
  area.origin_x_m = min_x;
  area.origin_y_m = min_y;
  mapping::MappingConfig mapping;
  mapping.resolution_m = resolution;
  const mapping::DualMap map(tree.Clone(), mapping);
  MapProjector projector(std::move(area), config);
  (void)projector.ProjectAll(DualMapView(map));
  return projector.map();
}

std::vector<Eigen::Vector2f> TouchedColumns(const robotio::DepthRays& rays, const GridMap& area) {
  std::vector<std::uint8_t> touched(area.cells.size(), 0);
  std::vector<Eigen::Vector2f> columns;
  const auto mark = [&](double x, double y) {
    const GridIndex c = area.CellAt(x, y);
    if (!area.Contains(c)) return;
    std::uint8_t& t = touched[area.Index(c)];
    if (t != 0) return;
    t = 1;
    columns.emplace_back(static_cast<float>(area.CenterX(c.x)), static_cast<float>(area.CenterY(c.y)));
  };
  // Seen from above, a frame's rays fan out from one origin, and the rays of one image
  // column nearly overlap. Rays are grouped by bearing into bins narrow enough that, out
  // to the longest ray, any two in a bin stay within half a cell of each other; only the
  // longest of each bin is walked (a 320 px frame: a few hundred walks, not 19,200).
  const Eigen::Vector2d o = rays.origin.head<2>().cast<double>();
  double longest = 0.0;
  for (const Eigen::Vector3f& end : rays.ends) {
    longest = std::max(longest, (end.head<2>().cast<double>() - o).norm());
  }
  const double step = 0.5 * area.resolution_m;  // Half-cell steps: no column is skipped
                                                // by more than a corner sliver.
  mark(o.x(), o.y());
  if (longest < step) return columns;
  const int bins = static_cast<int>(std::ceil(2.0 * M_PI * longest / step));
  std::vector<Eigen::Vector2d> far(static_cast<std::size_t>(bins), Eigen::Vector2d::Zero());
  for (const Eigen::Vector3f& end : rays.ends) {
    const Eigen::Vector2d d = end.head<2>().cast<double>() - o;
    const double angle = std::atan2(d.y(), d.x()) + M_PI;  // [0, 2π]
    const int bin = std::min(bins - 1, static_cast<int>(angle / (2.0 * M_PI) * bins));
    Eigen::Vector2d& kept = far[static_cast<std::size_t>(bin)];
    if (d.squaredNorm() > kept.squaredNorm()) kept = d;
  }
  for (const Eigen::Vector2d& d : far) {
    const int steps = static_cast<int>(std::ceil(d.norm() / step));
    for (int i = 1; i <= steps; ++i) {
      const double t = static_cast<double>(i) / steps;
      mark(o.x() + t * d.x(), o.y() + t * d.y());
    }
  }
  return columns;
}

std::vector<Eigen::Vector2f> HitColumns(const robotio::DepthRays& rays, const GridMap& area,
                                        double min_z_m, double max_z_m) {
  std::vector<std::uint8_t> hit(area.cells.size(), 0);
  std::vector<Eigen::Vector2f> columns;
  for (std::size_t i = 0; i < rays.ends.size(); ++i) {
    const Eigen::Vector3f& end = rays.ends[i];
    if (!rays.hit[i] || end.z() <= min_z_m || end.z() >= max_z_m) continue;
    const GridIndex c = area.CellAt(end.x(), end.y());
    if (!area.Contains(c) || hit[area.Index(c)] != 0) continue;
    hit[area.Index(c)] = 1;
    columns.emplace_back(static_cast<float>(area.CenterX(c.x)), static_cast<float>(area.CenterY(c.y)));
  }
  return columns;
}

}  // namespace dynamap::planning
