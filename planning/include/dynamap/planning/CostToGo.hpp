// Path cost from one cell to every cell of the traversal grid (Dijkstra over the same
// moves and costs as the path planners): target planning's reachability and path-cost term.
#pragma once

#include <vector>

#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

// Cost in cells (multiply by the resolution for metres); kInfinity where unreachable.
[[nodiscard]] std::vector<double> CostToGo(const TraversalGrid& grid, GridIndex source);

}  // namespace dynamap::planning
