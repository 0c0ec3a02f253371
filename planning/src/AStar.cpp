#include "dynamap/planning/AStar.hpp"

#include <algorithm>
#include <queue>

namespace dynamap::planning {

namespace {

struct OpenEntry {
  double f;
  double g;
  int index;
  // Min-heap on f; among equal f prefer the deeper node (larger g), which reaches the goal
  // with fewer expansions on open grids.
  friend bool operator<(const OpenEntry& a, const OpenEntry& b) {
    return a.f > b.f || (a.f == b.f && a.g < b.g);
  }
};

}  // namespace

GridPath AStarSearch(const TraversalGrid& grid, GridIndex start, GridIndex goal) {
  GridPath result;
  if (grid.Blocked(start) || grid.Blocked(goal)) return result;
  const std::size_t n = grid.penalty.size();
  std::vector<double> g(n, kInfinity);
  std::vector<int> parent(n, -1);
  std::vector<bool> closed(n, false);
  std::priority_queue<OpenEntry> open;
  const int start_index = grid.Index(start);
  const int goal_index = grid.Index(goal);
  g[start_index] = 0.0;
  open.push({OctileDistance(start, goal), 0.0, start_index});
  while (!open.empty()) {
    const OpenEntry top = open.top();
    open.pop();
    if (closed[top.index]) continue;  // Stale duplicate (lazy decrease-key).
    closed[top.index] = true;
    ++result.expansions;
    if (top.index == goal_index) break;
    const GridIndex u = grid.Cell(top.index);
    for (const Move& m : kMoves) {
      const double c = grid.MoveCost(u, m);
      if (c == kInfinity) continue;
      const GridIndex v{u.x + m.dx, u.y + m.dy};
      const int vi = grid.Index(v);
      const double candidate = top.g + c;
      if (!closed[vi] && candidate < g[vi]) {
        g[vi] = candidate;
        parent[vi] = top.index;
        open.push({candidate + OctileDistance(v, goal), candidate, vi});
      }
    }
  }
  if (!closed[goal_index]) return result;
  result.found = true;
  result.cost = g[goal_index];
  for (int i = goal_index; i != -1; i = parent[i]) result.cells.push_back(grid.Cell(i));
  std::reverse(result.cells.begin(), result.cells.end());
  return result;
}

}  // namespace dynamap::planning
