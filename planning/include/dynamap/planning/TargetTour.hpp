// The order in which to visit every target: a tour from the robot through all target
// viewpoints to the start, where the mission ends. Choosing each next target greedily by
// gain over path cost leaves small regions behind and drives back for them (in the office
// two thirds of the default planner's path went to inspection viewpoints; docs/RESULTS.md).
// Like FUEL's global tour (Zhou et al., 2021) the "tour" strategy orders the viewpoints by
// the shortest tour found (nearest neighbour, then 2-opt) and scores each target by the
// length of the tour that visits it first.
#pragma once

#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

struct TourCosts {
  std::vector<double> from_robot;             // m, robot to stop i.
  std::vector<std::vector<double>> between;   // m, stop i to stop j (symmetric).
  std::vector<double> to_end;                 // m, stop i to the end of the tour.
};

// Total length of robot → order[0] → … → order.back() → end.
[[nodiscard]] double TourLength(const std::vector<int>& order, const TourCosts& costs);

// The shortest tour found that visits `first` first: nearest neighbour from `first`, then
// 2-opt over the stops after it (the end stays fixed).
[[nodiscard]] std::vector<int> TourFrom(int first, const TourCosts& costs);

// For each stop, the length of TourFrom(stop).
[[nodiscard]] std::vector<double> TourLengthsByFirstStop(const TourCosts& costs);

// Path distances (m) from each of `from` to each of `to`, on `grid` coarsened `factor`
// times per axis (a coarse cell is passable when any of its cells is, so no way of the
// grid is lost; a blocked band narrower than two coarse cells may be crossed, which the
// inflation around walls, 0.72 m and more, never leaves; proximity penalties are left
// out). For ordering, not for driving: where no way is found the straight line counts
// three times.
[[nodiscard]] std::vector<std::vector<double>> CoarseDistances(const TraversalGrid& grid,
                                                              const std::vector<GridIndex>& from,
                                                              const std::vector<GridIndex>& to,
                                                              int factor, double resolution_m);

}  // namespace dynamap::planning
