// Which wall and furniture surfaces (obstacle cells of the projected map) have been seen
// from within the inspection distance: the bookkeeping behind inspection targets (thesis
// 6.2; DESIGN.md, surface_coverage).
#pragma once

#include <cstdint>
#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::planning {

struct SurfaceCoverageConfig {
  double inspection_distance_m = 2.5;  // m, a surface counts as inspected when seen from closer.
  double sensor_fov_rad = 2.0;         // rad, horizontal opening of both Kinects together
                                       // (two 57° views yawed ±29°), centred on the heading.
};

class SurfaceCoverage {
 public:
  explicit SurfaceCoverage(SurfaceCoverageConfig config = {}) : config_(config) {}

  // Marks the obstacle cells visible from `pose` (map frame) within the inspection distance.
  void Observe(const GridMap& map, const robotio::Pose2D& pose);
  [[nodiscard]] bool Inspected(int index) const {
    return index < static_cast<int>(inspected_.size()) && inspected_[index] != 0;
  }
  // Inspected, or next to an inspected cell: a wall's cells shift by one as the map firms
  // up, and the new ones were seen as closely as their neighbours.
  [[nodiscard]] bool InspectedNear(const GridMap& map, GridIndex c) const;
  // Surface cells: obstacle cells with a navigable 4-neighbour (what the robot can face).
  [[nodiscard]] static bool IsSurface(const GridMap& map, GridIndex c);
  // Share of the map's surface cells inspected so far (1 when there are none).
  [[nodiscard]] double Fraction(const GridMap& map) const;
  [[nodiscard]] const SurfaceCoverageConfig& config() const { return config_; }

 private:
  SurfaceCoverageConfig config_;
  std::vector<std::uint8_t> inspected_;  // Per cell of the last map seen (same layout).
};

}  // namespace dynamap::planning
