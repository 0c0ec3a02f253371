// The last way to a goal when the planner's grid has none: the same grid inflated by the
// robot's radius less half a cell. The inflation measures between cell centres, while an
// obstacle cell stands for a surface anywhere inside it, so the full radius can close a
// doorway the robot fits through. In the office (seed 4) the 0.86 m clear opening of an
// open door was mapped 0.75 m between obstacle cell centres, the leaf three cells thick and
// the post one cell in; with 0.36 m on each side no cell was left, the robot 0.72 m wide
// stood in the room for 16 minutes without a path home. Half a cell less leaves the cells
// in the middle of such a doorway and nothing through a gap narrower than the robot.
#pragma once

#include <optional>

#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

struct SqueezePath {
  TraversalGrid grid;  // The grid inflated by the smaller radius (for path shortening).
  GridPath path;       // From `robot` to `goal` on it.
};

// m a squeeze takes off the robot's radius: half a cell, by which an obstacle cell's
// centre may lie beyond the surface it holds (a doorway mapped a cell narrower a side).
[[nodiscard]] double SqueezeAllowance(double resolution_m);
// The robot's radius used for squeezing: `cost.robot_radius_m` less SqueezeAllowance.
[[nodiscard]] double SqueezeRadius(const CostFieldConfig& cost, double resolution_m);

// `map` inflated by SqueezeRadius, with holes kept at their full distance (radius plus
// margin).
[[nodiscard]] TraversalGrid BuildSqueezeGrid(const GridMap& map, const CostFieldConfig& cost);

// A path from `robot` to `goal` on `map` inflated by SqueezeRadius (holes keep their full
// margin; the robot's own cell never blocks), or nothing when there is none either.
[[nodiscard]] std::optional<SqueezePath> FindSqueezePath(const GridMap& map,
                                                         const CostFieldConfig& cost,
                                                         GridIndex robot, GridIndex goal);
// The same on a squeeze grid already built from the map (BuildSqueezeGrid).
[[nodiscard]] std::optional<SqueezePath> FindSqueezePath(TraversalGrid squeeze_grid,
                                                         GridIndex robot, GridIndex goal);

}  // namespace dynamap::planning
