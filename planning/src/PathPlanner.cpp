#include "dynamap/planning/PathPlanner.hpp"

#include <cassert>

#include "dynamap/planning/AStar.hpp"
#include "dynamap/planning/CostField.hpp"

namespace dynamap::planning {

PathPlanner::PathPlanner(std::string planner, TraversalGrid grid)
    : incremental_(planner != "astar"), grid_(std::move(grid)) {
  assert(planner == "dstar" || planner == "astar");
}

void PathPlanner::SetGrid(const TraversalGrid& grid) {
  assert(grid.width == grid_.width && grid.height == grid_.height);
  if (dstar_) dstar_->UpdateCells(DiffGrids(grid_, grid));
  grid_ = grid;
}

void PathPlanner::SetGoal(GridIndex goal) {
  goal_ = goal;
  // A new goal invalidates everything D* Lite knows; the search restarts.
  if (incremental_) dstar_.emplace(grid_, start_, goal);
}

void PathPlanner::MoveStart(GridIndex start) {
  start_ = start;
  if (dstar_) dstar_->MoveStart(start);
}

GridPath PathPlanner::Plan() {
  if (!goal_) return {};
  if (dstar_) return dstar_->Plan();
  return AStarSearch(grid_, start_, *goal_);
}

}  // namespace dynamap::planning
