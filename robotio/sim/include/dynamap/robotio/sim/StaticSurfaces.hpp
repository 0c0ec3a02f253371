// Ground truth for the mapping evaluation: points on every surface that the final static
// map should hold (static_map_precision / static_map_completeness, DESIGN.md).
#pragma once

#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::robotio::sim {

// Points in the map frame, about spacing_m apart, on the floor minus holes, the walls,
// steps, fixed furniture and doors/movable furniture in their placement at
// world.duration_s (set it to the recording's duration first). Hole pits are left out:
// they are below the floor and not part of the traversable static structure.
[[nodiscard]] PointList SampleStaticSurfaces(const World& world, double spacing_m);

}  // namespace dynamap::robotio::sim
