// Whether the robot, having reached its target's viewpoint, is still turning to look at
// the target: the planner leaves the target alone meanwhile. Judged earlier, a viewpoint
// within TargetSelection's near_m counts as "at the robot's feet", and so as failed,
// before the robot has looked from it. That blacklisted, unseen, the office's S3 frontier
// (seed 1): the robot, at 0.8 m/s, came 0.2-0.35 m short of the viewpoint between two
// plans, nearer than near_m but not within the goal tolerance, which the turning waited
// for. So the robot has arrived here at the same distance as near_m.
#pragma once

#include <optional>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TargetPlanner.hpp"
#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::planning {

struct ViewpointArrivalConfig {
  double arrived_m = 0.35;          // m, the robot this close to the viewpoint has reached
                                    // it (TargetSelectionConfig::near_m).
  double face_tolerance_rad = 0.2;  // rad, heading error within which it faces the target.
  double face_timeout_s = 6.0;      // s of turning at the viewpoint before the target is
                                    // judged anyway.
};

class ViewpointArrival {
 public:
  explicit ViewpointArrival(ViewpointArrivalConfig config = {}) : config_(config) {}

  // True while the robot at `pose` stands within arrived_m of `target`'s viewpoint, does not
  // yet face its region centre, and has not been there longer than face_timeout_s. Cells
  // are `map`'s; no target (or driving away) starts the next arrival afresh.
  [[nodiscard]] bool StillFacing(const GridMap& map, const std::optional<TargetCandidate>& target,
                                 const robotio::Pose2D& pose, double now_s);

 private:
  ViewpointArrivalConfig config_;
  std::optional<double> arrived_s_;  // When the robot reached the current viewpoint.
};

}  // namespace dynamap::planning
