// The planning thread of the mission runtime (thesis 6.2-6.3): on the newest projected
// grid, chooses a target (frontier, inspection or home), plans to it with D* Lite
// (incrementally while the goal stays), shortens the path and publishes it. Declares the
// exploration complete when the planner finds nothing worth reaching and the robot is home.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "dynamap/app/runtime/Mediator.hpp"
#include "dynamap/planning/BlockedWay.hpp"
#include "dynamap/planning/PathPlanner.hpp"
#include "dynamap/planning/PlanningConfig.hpp"
#include "dynamap/planning/SurfaceCoverage.hpp"
#include "dynamap/planning/TargetPlanner.hpp"
#include "dynamap/planning/TargetSelection.hpp"
#include "dynamap/planning/TemporaryObstacles.hpp"
#include "dynamap/planning/ViewpointArrival.hpp"

namespace dynamap::app::runtime {

struct PlanningWorkerConfig {
  planning::PlanningConfig planning;
  double known_floor_radius_m = 0.8;  // m around visited poses: unseen floor is drivable.
  // m around the start: the operator puts the robot down on clear floor, and the Kinects
  // never see the ring just beyond the robot (robotio::FloorBlindRadius), not even turning
  // in place; without this the start would be an island among unknown cells.
  double start_floor_radius_m = 1.3;
  double target_timeout_s = 60.0;     // s without reaching a goal before it counts as failed.
  double blocked_wait_s = 10.0;       // s the robot waits for people blocking its way
                                      // before the target counts as unreachable.
  double face_timeout_s = 6.0;        // s at a viewpoint, turning to face its target,
                                      // before the target is judged again.
  double resolution_m = 0.05;         // m, cell edge of the projected map.
};

class PlanningWorker {
 public:
  PlanningWorker(Mediator& mediator, PlanningWorkerConfig config);

  void Run();  // Thread body: until the mission stops.
  // One plan at mission time `now_s` on the mediator's newest grid and pose, published as
  // its plan (Run calls it every replan period).
  void PlanOnce(double now_s);

  [[nodiscard]] const std::vector<double>& plan_ms() const { return plan_ms_; }
  [[nodiscard]] const planning::SurfaceCoverage& coverage() const { return coverage_; }

 private:
  // m, the robot this near a viewpoint has reached it: there it looks, and a viewpoint this
  // near is not chosen again (twice the follower's goal tolerance plus a cell).
  [[nodiscard]] double ArrivedM() const;
  // `seen` with the floor around visited places (too close for the Kinects) drivable.
  [[nodiscard]] planning::GridMap PrepareGrid(const planning::GridMap& seen,
                                              const robotio::Pose2D& pose) const;

  Mediator& mediator_;
  PlanningWorkerConfig config_;
  planning::TargetPlanner targets_;
  planning::SurfaceCoverage coverage_;
  planning::TemporaryObstacles obstacles_;
  planning::BlockedWay blocked_;  // Waits for people in the way before giving a goal up.
  std::unique_ptr<planning::PathPlanner> search_;  // D* Lite (or A*), kept across plans.
  planning::GridIndex goal_{-1, -1};
  planning::TargetCandidate goal_target_;  // What the goal was chosen for (blacklisting).
  std::optional<planning::TargetCandidate> current_target_;  // Kept across re-plans.
  planning::DroppedTargetKeeper dropped_;  // A target that drops out, still driven to.
  planning::ViewpointArrival arrival_;  // Not judged while turning to look from there.
  double goal_since_s_ = 0.0;
  std::vector<double> plan_ms_;
};

}  // namespace dynamap::app::runtime
