// The control thread of the mission runtime (thesis ch. 7): at a fixed rate of simulated
// time, checks the newest raw depth frames with the collision guard (it never waits on SLAM
// or planning), follows the newest planned path, and publishes the velocity command. What
// the frames showed at robot height is remembered for a few seconds in the odometry frame
// (planning::ObstacleMemory; longer where no Kinect can see it again), and the path is
// shifted off it where SLAM's map pose is off the map (planning::PathShift).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "dynamap/app/runtime/Mediator.hpp"
#include "dynamap/planning/CollisionGuard.hpp"
#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/FieldOfView.hpp"
#include "dynamap/planning/ObstacleMemory.hpp"
#include "dynamap/planning/PathFollower.hpp"
#include "dynamap/planning/PathShift.hpp"
#include "dynamap/planning/StallDetector.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::app::runtime {

struct ControlWorkerConfig {
  double rate_hz = 20.0;                  // Hz of simulated time.
  // s standing still at the start: the motion model learns the gyro bias meanwhile.
  double initial_still_s = 2.0;
  double look_around_yaw_rate = 0.5;      // rad/s of the first look around.
  double initial_turn_rad = 6.3;          // rad turned in place before following plans.
  double recovery_s = 1.0;                // s of the guard's recovery motion after a stop.
  double stall_backoff_s = 2.0;           // s backing away (at the guard's back-off speed)
                                          // from what a stalled base pressed against.
  double map_guard_s = 0.5;               // s ahead the map guard checks the footprint.
  // s the map guard may hold back a base the follower drives before the way ahead is
  // reported to the planner as blocked (StallObstacle, as for a stall).
  double map_guard_give_up_s = 5.0;
  planning::PathFollowerConfig follower;
  planning::CollisionGuardConfig guard;
  planning::StallDetectorConfig stall;
  planning::CostFieldConfig cost;         // To read clearance off the planner's cost grid.
  planning::ObstacleMemoryConfig memory;
  planning::PathShiftConfig path_shift;
};

class ControlWorker {
 public:
  ControlWorker(Mediator& mediator, robotio::Rig rig, ControlWorkerConfig config);
  void Run();  // Thread body: until the mission stops; leaves the base commanded to stop.
  // One control step at mission time `now_ns`, `dt_s` after the previous one: returns the
  // command, which is in force until the next step (Run publishes it).
  robotio::VelocityCommand Tick(std::int64_t now_ns, double dt_s);
  // m, map frame: the path shift in force (zero while nothing seen lately is near the path).
  [[nodiscard]] Eigen::Vector2d path_shift() const { return shift_.shift(); }

 private:
  [[nodiscard]] robotio::VelocityCommand Step(std::int64_t now_ns, double dt_s);
  // Robot-height points of the Kinects' frames that arrived since the last step (kept per
  // Kinect for the guard) into the memory; forgets what is too old.
  void TakeNewFrames(std::int64_t now_ns);
  // The pose the follower and the map guard use: SLAM's, moved back by the path shift.
  // `plan` may be null (no plan yet: no shift).
  [[nodiscard]] robotio::Pose2D PoseOnPath(const Plan* plan, const robotio::Pose2D& pose,
                                           double dt_s);
  // `command` with v = 0 when it would drive the footprint into a known obstacle of the
  // plan's map (planning::DrivesIntoKnownObstacle) both from SLAM's `pose` and from
  // `on_path` (the same when the path is not shifted); counted in map_guard_stops. The
  // footprint is the guard's, half a cell less on a squeezed path (Plan::squeezed).
  [[nodiscard]] robotio::VelocityCommand HoldAtKnownObstacles(const Plan* plan,
                                                              const robotio::Pose2D& pose,
                                                              const robotio::Pose2D& on_path,
                                                              robotio::VelocityCommand command);

  // `command` (HoldAtKnownObstacles' verdict on the follower's `wanted`), or a stop when
  // the map guard has now held the base for map_guard_give_up_s of steps that wanted to
  // drive: the way ahead then goes to the planner as blocked (counted in
  // map_guard_give_ups). Steps that drive start the count afresh.
  [[nodiscard]] robotio::VelocityCommand GiveUpALongHold(const robotio::Pose2D& pose,
                                                         const robotio::VelocityCommand& wanted,
                                                         robotio::VelocityCommand command,
                                                         double dt_s);

  Mediator& mediator_;
  robotio::Rig rig_;
  ControlWorkerConfig config_;
  planning::PathFollower follower_;
  planning::StallDetector stall_;
  planning::ObstacleMemory memory_;
  planning::FieldOfView view_;  // Where the Kinects see: what the memory may forget.
  planning::PathShift shift_;
  std::array<std::uint64_t, kMaxKinects> frame_version_{};  // Last frame taken per Kinect.
  std::array<std::vector<Eigen::Vector2d>, kMaxKinects> frame_points_;  // Its points, base.
  std::uint64_t plan_version_ = 0;
  robotio::VelocityCommand last_;
  std::int64_t recovery_until_ns_ = -1;
  robotio::VelocityCommand recovery_;
  double map_guard_held_s_ = 0.0;  // s the map guard has held the base since it last drove.
  double turned_rad_ = 0.0;
  std::int64_t start_ns_ = -1;  // First control step.
};

}  // namespace dynamap::app::runtime
