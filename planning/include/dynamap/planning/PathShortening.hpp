// Path post-processing for following (thesis 6.3): the grid path's cells reduced to the
// waypoints between which the straight segment stays clear, so the follower drives lines
// rather than 45° zig-zags.
#pragma once

#include <vector>

#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

// True when every cell the segment between the two cell centres touches is free and, with
// `max_penalty`, no such cell carries a larger proximity penalty (keeps shortcuts from
// hugging walls the cost field steered the path away from).
[[nodiscard]] bool LineOfSight(const TraversalGrid& grid, GridIndex a, GridIndex b,
                               double max_penalty = kInfinity);

// Greedy shortening: from each kept waypoint, jump to the farthest later cell in sight.
[[nodiscard]] std::vector<GridIndex> ShortenPath(const TraversalGrid& grid,
                                                 const std::vector<GridIndex>& cells);

}  // namespace dynamap::planning
