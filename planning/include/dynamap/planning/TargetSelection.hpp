// Which scored candidate the robot drives to, across re-plans. Scores move a little with
// every new scan, and without memory two targets of nearly equal score win in turn: the
// robot turns towards one, then the other, and never leaves (seen in the office, a
// frontier ahead against an unseen wall behind). So the current target is kept while it is
// still a candidate unless another scores clearly better, and a viewpoint at the robot's
// feet is never chosen (it shows nothing the robot does not see already).
#pragma once

#include <optional>
#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TargetPlanner.hpp"

namespace dynamap::planning {

struct TargetSelectionConfig {
  double near_m = 0.35;         // m, viewpoints this close to the robot are not chosen.
  double same_target_m = 0.75;  // m, a candidate of the same kind with its viewpoint (or,
                                // failing that, its region centre) this close to the
                                // current one's is the current target, re-scored.
  double switch_ratio = 1.5;    // Another candidate must score this many times more.
};

struct TargetSelection {
  std::optional<TargetCandidate> chosen;   // None: every candidate is at the robot's feet.
  std::vector<TargetCandidate> too_near;   // Candidates skipped for being at the robot.
  bool kept_current = false;               // The current target was kept.
};

// `current` is the target being driven to (none after reaching one or at the start).
[[nodiscard]] TargetSelection SelectTarget(const std::vector<TargetCandidate>& candidates,
                                           const std::optional<TargetCandidate>& current,
                                           const GridMap& map, GridIndex robot,
                                           const TargetSelectionConfig& config);

}  // namespace dynamap::planning
