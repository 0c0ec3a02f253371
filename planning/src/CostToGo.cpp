#include "dynamap/planning/CostToGo.hpp"

#include <queue>
#include <utility>

namespace dynamap::planning {

std::vector<double> CostToGo(const TraversalGrid& grid, GridIndex source) {
  std::vector<double> cost(grid.penalty.size(), kInfinity);
  if (grid.Blocked(source)) return cost;
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
  cost[grid.Index(source)] = 0.0;
  open.push({0.0, grid.Index(source)});
  while (!open.empty()) {
    const auto [c, i] = open.top();
    open.pop();
    if (c > cost[i]) continue;  // Stale entry.
    const GridIndex u = grid.Cell(i);
    for (const Move& m : kMoves) {
      const double step = grid.MoveCost(u, m);
      if (step == kInfinity) continue;
      const int j = grid.Index({u.x + m.dx, u.y + m.dy});
      if (c + step < cost[j]) {
        cost[j] = c + step;
        open.push({cost[j], j});
      }
    }
  }
  return cost;
}

}  // namespace dynamap::planning
