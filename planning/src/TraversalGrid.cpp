#include "dynamap/planning/TraversalGrid.hpp"

#include <cstdlib>

namespace dynamap::planning {

double PathCost(const TraversalGrid& grid, const std::vector<GridIndex>& cells) {
  if (cells.empty()) return kInfinity;
  if (grid.Blocked(cells.front())) return kInfinity;
  double cost = 0.0;
  for (std::size_t i = 1; i < cells.size(); ++i) {
    const int dx = cells[i].x - cells[i - 1].x;
    const int dy = cells[i].y - cells[i - 1].y;
    if (std::abs(dx) > 1 || std::abs(dy) > 1 || (dx == 0 && dy == 0)) return kInfinity;
    const Move move{dx, dy, dx != 0 && dy != 0 ? kSqrt2 : 1.0};
    cost += grid.MoveCost(cells[i - 1], move);
  }
  return cost;
}

}  // namespace dynamap::planning
