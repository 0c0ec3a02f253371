#include "dynamap/planning/BlockedWay.hpp"

#include <algorithm>
#include <cmath>

#include "dynamap/planning/AStar.hpp"

namespace dynamap::planning {

GridMap WithoutDynamicObstacles(const GridMap& grid, const std::vector<int>& dynamic_obstacles) {
  GridMap cleared = grid;
  for (const int i : dynamic_obstacles) {
    if (cleared.cells[static_cast<std::size_t>(i)] == CellState::kObstacle) {
      cleared.cells[static_cast<std::size_t>(i)] = CellState::kNavigable;
    }
  }
  return cleared;
}

BlockedWayVerdict BlockedWay::Judge(const TraversalGrid* passable, GridIndex robot, GridIndex goal,
                                    double resolution_m, double now_s) {
  if (!since_s_) since_s_ = now_s;
  BlockedWayVerdict verdict;
  verdict.blocked_for_s = now_s - *since_s_;
  if (passable == nullptr || verdict.blocked_for_s >= config_.wait_s) {
    since_s_.reset();
    return verdict;
  }
  const GridPath around = AStarSearch(*passable, robot, goal);
  if (!around.found || around.cells.empty()) {
    since_s_.reset();
    return verdict;
  }
  const auto ahead = static_cast<std::size_t>(std::ceil(config_.look_ahead_m / resolution_m));
  verdict.wait = true;
  verdict.look_at = around.cells[std::min(ahead, around.cells.size() - 1)];
  return verdict;
}

}  // namespace dynamap::planning
