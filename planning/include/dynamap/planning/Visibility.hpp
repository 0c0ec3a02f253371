// 2D visibility on the projected map for target planning (thesis 6.2): which cells a
// sensor at a cell would see, casting rays that stop at the first obstacle.
#pragma once

#include <vector>

#include "dynamap/planning/GridMap.hpp"

namespace dynamap::planning {

struct ViewCone {
  double range_m = 4.5;              // m, sensor range.
  double min_range_m = 0.0;          // m, nearer cells are passed but not counted as seen
                                     // (the floor just beyond the base is out of view).
  double heading_rad = 0.0;          // rad, centre direction in the map frame.
  double fov_rad = 6.283185307179586;  // rad, full opening angle (2π = all around).
  int rays = 90;                     // Rays over the opening angle.
};

// Indices of the cells seen from `from` (each once, in no particular order). A ray passes navigable and
// unknown cells and ends on the first obstacle (which is included: its surface is seen).
[[nodiscard]] std::vector<int> VisibleCells(const GridMap& map, GridIndex from, const ViewCone& cone);

}  // namespace dynamap::planning
