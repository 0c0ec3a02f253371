#include "dynamap/planning/SqueezePath.hpp"

#include <utility>

#include "dynamap/planning/AStar.hpp"

namespace dynamap::planning {

double SqueezeAllowance(double resolution_m) { return 0.5 * resolution_m; }

double SqueezeRadius(const CostFieldConfig& cost, double resolution_m) {
  return cost.robot_radius_m - SqueezeAllowance(resolution_m);
}

TraversalGrid BuildSqueezeGrid(const GridMap& map, const CostFieldConfig& cost) {
  CostFieldConfig squeezed = cost;
  squeezed.robot_radius_m = SqueezeRadius(cost, map.resolution_m);
  // A wall is bumped, a pit is fallen into: the stair hole keeps its whole distance.
  squeezed.hole_margin_m = cost.hole_margin_m + (cost.robot_radius_m - squeezed.robot_radius_m);
  return BuildTraversalGrid(map, squeezed);
}

std::optional<SqueezePath> FindSqueezePath(TraversalGrid squeeze_grid, GridIndex robot,
                                           GridIndex goal) {
  SqueezePath squeeze{std::move(squeeze_grid), {}};
  if (!squeeze.grid.Contains(robot) || squeeze.grid.Blocked(goal)) return std::nullopt;
  FreeStandingCell(squeeze.grid, robot);
  squeeze.path = AStarSearch(squeeze.grid, robot, goal);
  if (!squeeze.path.found) return std::nullopt;
  return squeeze;
}

std::optional<SqueezePath> FindSqueezePath(const GridMap& map, const CostFieldConfig& cost,
                                           GridIndex robot, GridIndex goal) {
  return FindSqueezePath(BuildSqueezeGrid(map, cost), robot, goal);
}

}  // namespace dynamap::planning
