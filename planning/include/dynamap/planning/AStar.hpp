// Plain A* on the traversal grid (Hart, Nilsson & Raphael 1968): the from-scratch
// reference that D* Lite's costs are tested and benchmarked against (thesis 6.3).
#pragma once

#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

// Optimal 8-connected path from start to goal (octile heuristic); found = false when the
// goal is unreachable or either end is blocked.
[[nodiscard]] GridPath AStarSearch(const TraversalGrid& grid, GridIndex start, GridIndex goal);

}  // namespace dynamap::planning
