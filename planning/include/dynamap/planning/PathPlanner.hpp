// The path planner the mission runtime holds (thesis 6.3): D* Lite repairing its search as
// the grid changes and the robot moves, or A* from scratch every time (`planner: astar`,
// the reference), behind one interface.
#pragma once

#include <optional>
#include <string>

#include "dynamap/planning/DStarLite.hpp"
#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

class PathPlanner {
 public:
  // `planner` is "dstar" or "astar" (PlanningConfig::planner).
  PathPlanner(std::string planner, TraversalGrid grid);

  // A new traversal grid (same size): D* Lite gets only the cells that differ.
  void SetGrid(const TraversalGrid& grid);
  void SetGoal(GridIndex goal);
  void MoveStart(GridIndex start);
  // Path from the current start to the goal; not found without a goal.
  [[nodiscard]] GridPath Plan();

  [[nodiscard]] const TraversalGrid& grid() const { return grid_; }
  [[nodiscard]] const std::optional<GridIndex>& goal() const { return goal_; }

 private:
  bool incremental_;
  TraversalGrid grid_;
  GridIndex start_;
  std::optional<GridIndex> goal_;
  std::optional<DStarLite> dstar_;  // Exists while incremental and a goal is set.
};

}  // namespace dynamap::planning
