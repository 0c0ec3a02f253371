// Projected map → traversal grid: obstacles and holes inflated by the robot radius (unknown
// cells by a smaller radius) and a
// proximity penalty that decays with the distance to them (distance transform; thesis 6.1,
// 6.3). Also the cell-wise difference two grids hand to D* Lite as edge changes.
#pragma once

#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

struct CostFieldConfig {
  double robot_radius_m = 0.36;     // m, the footprint radius: cells nearer than this to an
                                    // obstacle or hole are blocked. Obstacle cell centres may
                                    // lie up to half a cell beyond the surface; a larger
                                    // radius (0.38 m) closed the 0.9 m office doors, and the
                                    // map guard covers the difference.
  double hole_margin_m = 0.2;       // m kept from a hole (a stair pit) beyond the radius: a
                                    // wall is bumped, a pit is fallen into. Without it the
                                    // office robot drove through the 0.9 m between the pit
                                    // and a wall, and twice its footprint touched the pit's
                                    // corner; with 0.15 m it came within 0.39 m of the corner
                                    // (docs/RESULTS.md, "The stair pit's corner").
  double proximity_range_m = 0.5;   // m beyond the radius over which the penalty decays to 0.
  double proximity_weight = 2.0;    // Penalty at the inflated boundary (relative extra cost).
  bool unknown_is_obstacle = true;  // Unknown cells block (inflated by unknown_radius_m);
                                    // false plans optimistically through them.
  double unknown_radius_m = 0.2;    // m, cells nearer than this to unknown ones are blocked.
                                    // Less than the robot radius: beside a door post or a
                                    // desk the floor in its shadow stays unseen, and a full
                                    // inflation of it closes doorways the robot fits through.
                                    // The footprint may overhang unseen floor by the
                                    // difference; the collision guard watches it.
};

[[nodiscard]] TraversalGrid BuildTraversalGrid(const GridMap& map, const CostFieldConfig& config);

// Free distance from the robot's footprint edge to the nearest obstacle at `cell`, m, as
// the cost field knows it: 0 when blocked, exact within the proximity range, and
// `proximity_range_m` (a lower bound) beyond it. The path follower's clearance input.
[[nodiscard]] double Clearance(const TraversalGrid& grid, GridIndex cell,
                               const CostFieldConfig& config);

// A robot that stands where the grid is blocked (a pit's edge seen late widens the margin
// kept from it over the robot, a wall drawn nearer) must still have a way out, or nothing
// is reachable and it stands there for good. The blocked cells around it that are floor
// and no nearer to an obstacle or hole than the robot itself, within the inflation
// radius (robot radius + hole margin) and joined to it through such cells, become passable
// with kStandingCellPenalty: paths leave by the shortest way and never closer to what
// blocked them. Nothing changes when the robot's cell is passable or off the grid.
void FreeWayOut(TraversalGrid& grid, const GridMap& map, GridIndex robot,
                const CostFieldConfig& config);

// Every passable cell penalty 0, the rest blocked (Moving AI maps, tests).
[[nodiscard]] TraversalGrid TraversalFromPassable(int width, int height,
                                                  const std::vector<bool>& passable);

struct CellChange {
  int index = 0;          // Row-major cell index.
  double penalty = 0.0;   // New penalty (kInfinity = blocked).
};

// Cells whose penalty differs between two grids of the same size.
[[nodiscard]] std::vector<CellChange> DiffGrids(const TraversalGrid& before,
                                                const TraversalGrid& after);

}  // namespace dynamap::planning
