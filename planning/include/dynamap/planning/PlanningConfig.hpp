// Every planning and control setting in one struct, read from the `planning:` YAML section
// strictly (unknown keys, wrong types and out-of-range values name file, key and range).
#pragma once

#include <string>

#include "dynamap/planning/CollisionGuard.hpp"
#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/MapProjection.hpp"
#include "dynamap/planning/ObstacleMemory.hpp"
#include "dynamap/planning/PathFollower.hpp"
#include "dynamap/planning/PathShift.hpp"
#include "dynamap/planning/SurfaceCoverage.hpp"
#include "dynamap/planning/TargetPlanner.hpp"
#include "dynamap/robotio/ConfigReader.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::planning {

struct PlanningConfig {
  std::string planner = "dstar";          // "dstar" (incremental) or "astar" (from scratch).
  double replan_period_s = 0.5;           // s between target re-evaluations while driving.
  double temporary_obstacle_s = 10.0;     // s a collision-guard obstacle stays on the grid.
  ProjectionConfig projection;            // 3D map → 2D grid.
  CostFieldConfig cost;                   // Inflation and proximity cost.
  TargetPlannerConfig targets;            // Frontier / inspection targets.
  SurfaceCoverageConfig coverage;         // Inspection distance and sensor opening.
  PathFollowerConfig follower;            // (v, ω) control.
  CollisionGuardConfig guard;             // Depth-frame collision guard.
  ObstacleMemoryConfig memory;            // Robot-height points seen lately (odometry frame).
  PathShiftConfig path_shift;             // Path moved off them where the map pose is off.
};

// Reads the keys of `node` (the `planning:` mapping) over the defaults in `config`.
[[nodiscard]] PlanningConfig ParsePlanningConfig(robotio::ConfigNode& node,
                                                 PlanningConfig config = {});
// A whole file whose root is the planning mapping.
[[nodiscard]] robotio::Expected<PlanningConfig> LoadPlanningConfig(const std::string& file);

}  // namespace dynamap::planning
