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

// The true wall/furniture surface samples (0.2 m to robot height) visible from a
// reachable cell within the inspection distance, split by whether they were seen closely.
// Visible: along one of 24 directions the sample's own solid ends within 1.5 cells and a
// reachable cell follows within the distance, with no other solid in between; so the
// outer faces of outer walls and faces inside a piece of furniture's footprint (under a
// table top) do not count.
struct SurfaceCoverageResult {
  robotio::PointList inspected;
  robotio::PointList missed;
  [[nodiscard]] double Fraction() const {  // surface_coverage; 0 when nothing is visible.
    const std::size_t visible = inspected.size() + missed.size();
    return visible == 0 ? 0.0 : static_cast<double>(inspected.size()) / static_cast<double>(visible);
  }
};

// Splits `samples` as above; `inspected` says whether a sample was seen closely.
[[nodiscard]] SurfaceCoverageResult SurfaceCoverage(
    const TruthGrid& truth, const robotio::PointList& samples, double robot_height_m,
    double inspection_distance_m, const std::function<bool(const Eigen::Vector3f&)>& inspected);

}  // namespace dynamap::app::runtime
