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
  // Of those, the ones the robot has looked from, which count as failed: the current
  // target (reached, and ViewpointArrival has let it turn to look), or all of them when
  // none is left to drive to (the robot stays there). Not a viewpoint the robot passes on
  // the way to another target: that blacklisted the office's S3 room unchosen (seed 2),
  // its viewpoint in the corridor in front of its doorway.
  std::vector<TargetCandidate> looked_from_here;
  bool kept_current = false;               // The current target was kept.
};

// `current` is the target being driven to (none after reaching one or at the start).
[[nodiscard]] TargetSelection SelectTarget(const std::vector<TargetCandidate>& candidates,
                                           const std::optional<TargetCandidate>& current,
                                           const GridMap& map, GridIndex robot,
                                           const TargetSelectionConfig& config);

// A target that drops out of the candidates before the robot gets there. Its gain is
// counted from a viewpoint picked for where the robot stands, so a region can drop out
// and come back as the robot drives; following that, the robot turned back and forth
// between it and home until the time was up (small office). It is driven to for a while
// longer instead. (Frontiers too: kept for inspection targets only, the small office
// was completed in 1 of 3 runs within 240 s, against 4 of 6 with frontiers kept as well.)
struct DroppedTargetConfig {
  double arrived_m = 0.35;      // m, the robot this close to the viewpoint has reached it.
  double same_region_m = 0.5;   // m, a candidate whose region centre is this close is it.
  double grace_s = 10.0;        // s a dropped target is still driven to.
  double better_ratio = 2.0;    // A new target scoring this many times more wins at once.
};

class DroppedTargetKeeper {
 public:
  explicit DroppedTargetKeeper(DroppedTargetConfig config = {}) : config_(config) {}
  // `previous` was driven to before this plan, `next` is this plan's choice (none: go
  // home). Returns `previous` when it is to be kept instead: not reached, not among the
  // `candidates` any more, `next` not it and not twice as good, and dropped out no longer
  // than grace_s ago.
  [[nodiscard]] std::optional<TargetCandidate> Keep(
      const std::optional<TargetCandidate>& previous, const std::optional<TargetCandidate>& next,
      const std::vector<TargetCandidate>& candidates, const GridMap& map, GridIndex robot,
      double now_s);

 private:
  DroppedTargetConfig config_;
  std::optional<double> dropped_since_s_;
};

}  // namespace dynamap::planning
