#include "dynamap/planning/PathShortening.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace dynamap::planning {

namespace {

bool CellClear(const TraversalGrid& grid, GridIndex c, double max_penalty) {
  return !grid.Blocked(c) && grid.penalty[grid.Index(c)] <= max_penalty;
}

}  // namespace

bool LineOfSight(const TraversalGrid& grid, GridIndex a, GridIndex b, double max_penalty) {
  // Grid traversal (Amanatides & Woo) between cell centres, visiting every cell the segment
  // touches; where it passes exactly through a corner both side cells must be clear, the
  // same rule as the planner's no-corner-cutting.
  const int dx = std::abs(b.x - a.x);
  const int dy = std::abs(b.y - a.y);
  const int step_x = b.x > a.x ? 1 : -1;
  const int step_y = b.y > a.y ? 1 : -1;
  GridIndex c = a;
  if (!CellClear(grid, c, max_penalty)) return false;
  // Parameters in units of the segment's progress, scaled by 2·dx·dy to stay integral.
  long t_max_x = dx == 0 ? -1 : static_cast<long>(dy);  // First x boundary at half a cell.
  long t_max_y = dy == 0 ? -1 : static_cast<long>(dx);
  const long t_delta_x = 2L * dy;
  const long t_delta_y = 2L * dx;
  int remaining_x = dx;
  int remaining_y = dy;
  while (remaining_x > 0 || remaining_y > 0) {
    const bool step_in_x = remaining_x > 0 && (remaining_y == 0 || t_max_x <= t_max_y);
    const bool step_in_y = remaining_y > 0 && (remaining_x == 0 || t_max_y <= t_max_x);
    if (step_in_x && step_in_y) {
      if (!CellClear(grid, {c.x + step_x, c.y}, max_penalty) ||
          !CellClear(grid, {c.x, c.y + step_y}, max_penalty)) {
        return false;
      }
      c.x += step_x;
      c.y += step_y;
      t_max_x += t_delta_x;
      t_max_y += t_delta_y;
      --remaining_x;
      --remaining_y;
    } else if (step_in_x) {
      c.x += step_x;
      t_max_x += t_delta_x;
      --remaining_x;
    } else {
      c.y += step_y;
      t_max_y += t_delta_y;
      --remaining_y;
    }
    if (!CellClear(grid, c, max_penalty)) return false;
  }
  return true;
}

std::vector<GridIndex> ShortenPath(const TraversalGrid& grid, const std::vector<GridIndex>& cells) {
  if (cells.size() <= 2) return cells;
  std::vector<GridIndex> out{cells.front()};
  std::size_t i = 0;
  while (i + 1 < cells.size()) {
    // A shortcut may not lead through cells costlier than the ones the path itself used
    // between its ends, so the proximity cost keeps its effect after shortening.
    std::size_t best = i + 1;
    double path_max = std::max(grid.penalty[grid.Index(cells[i])],
                               grid.penalty[grid.Index(cells[i + 1])]);
    for (std::size_t j = i + 2; j < cells.size(); ++j) {
      path_max = std::max(path_max, grid.penalty[grid.Index(cells[j])]);
      if (LineOfSight(grid, cells[i], cells[j], path_max)) best = j;
    }
    out.push_back(cells[best]);
    i = best;
  }
  return out;
}

}  // namespace dynamap::planning
