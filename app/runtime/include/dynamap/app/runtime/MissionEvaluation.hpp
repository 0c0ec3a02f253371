// Exploration scores that need the simulator's truth (DESIGN.md, Evaluation):
// explored_free_fraction against the truly reachable floor, surface_coverage against the
// wall and furniture surfaces that can be seen from there within the inspection distance.
#pragma once

#include <functional>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::app::runtime {

struct TruthGrid {
  planning::GridMap reachable;  // kNavigable: a robot centre can stand there and get there
                                // from the start; kObstacle: solid; kUnknown: neither.
};

// Rasterises the world at `resolution_m` over `area` (map frame) at time `t_s`.
[[nodiscard]] TruthGrid BuildTruthGrid(const robotio::sim::World& world, planning::GridMap area,
                                       double footprint_radius_m, double robot_height_m,
                                       double t_s);

// Known-navigable share of the truly reachable cells of `truth`.
[[nodiscard]] double ExploredFreeFraction(const TruthGrid& truth, const planning::GridMap& known);

// Share of the true wall/furniture surface samples (0.2 m to robot height) visible from a
// reachable cell within `inspection_distance_m` that `inspected` says were seen closely.
[[nodiscard]] double SurfaceCoverage(const TruthGrid& truth, const robotio::PointList& samples,
                                     double robot_height_m, double inspection_distance_m,
                                     const std::function<bool(const Eigen::Vector3f&)>& inspected);

}  // namespace dynamap::app::runtime
