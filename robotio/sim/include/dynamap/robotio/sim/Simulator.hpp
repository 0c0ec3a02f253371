// The simulated robot in its world, stepped by the caller: velocity commands in;
// odometry (50 Hz), gyro (100 Hz), Kinect depth + label frames (when delivered, i.e.
// capture + latency), true pose and collision events out. Deterministic for a seed.
// Ground truth is in the map frame (origin and heading = the robot's start pose).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"
#include "dynamap/robotio/sim/CollisionWorld.hpp"
#include "dynamap/robotio/sim/DepthRenderer.hpp"
#include "dynamap/robotio/sim/DriveBaseModel.hpp"
#include "dynamap/robotio/sim/KinectModel.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"
#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::robotio::sim {

struct SimulatorConfig {
  std::uint64_t seed = 1;          // Every random draw derives from it.
  double physics_step_s = 0.002;   // s, base integration and collision check step.
  int render_threads = 2;          // Threads of the depth renderer.
  bool render_depth = true;        // false: proprioception only (no Kinect frames).
  bool stagger_kinects = true;     // Kinect i captures i/N of a frame period later, as
                                   // unsynchronised devices do.
  KinectModelConfig kinect;        // Depth error model of every Kinect.
  double yield_clearance_m = 0.3;  // m, a person who yields does not step nearer than this
                                   // to the robot's footprint; it waits until it may.
  double yield_patience_s = 5.0;   // s a person waits for a robot that stays in its way;
                                   // then it walks back the way it came, to
  double give_way_clearance_m = 1.5;  // m from the robot, and stands there for the patience
                                      // time before it tries again (no deadlock in a door).
  double schedule_clearance_m = 0.1;  // m from the footprint: a door is not shut or opened,
                                      // a chair not put down nearer to the robot than this;
                                      // its schedule waits until the robot has moved on.
};

struct CollisionEvent {
  std::int64_t stamp_ns = 0;
  std::string object_id;  // What the footprint touched.
  ObjectKind kind = ObjectKind::kWall;
  Pose2D pose;            // Base pose (map frame) where it stopped.
};

struct SimFrame {
  DepthFrame depth;                 // stamp_ns = capture, received_ns = capture + latency.
  LabelFrame labels;                // Same stamp as depth.
  StampedPose T_map_kinect;         // True sensor pose at the capture instant.
};

// Everything that became available during one Advance call, oldest first.
struct SimOutput {
  std::vector<OdometryReading> odometry;
  std::vector<ImuReading> imu;
  std::vector<SimFrame> frames;           // Delivered (received_ns <= now).
  std::vector<StampedPose> ground_truth;  // True T_map_base at the IMU rate.
  std::vector<CollisionEvent> collisions;
};

class Simulator {
 public:
  Simulator(World world, RobotConfig robot, Rig rig, SimulatorConfig config);

  // Takes effect from the current simulated time on (limits applied by the base).
  void SetCommand(const VelocityCommand& command);
  // Advances simulated time to t_ns (no-op when t_ns <= now).
  [[nodiscard]] SimOutput AdvanceTo(std::int64_t t_ns);
  [[nodiscard]] SimOutput Advance(double dt_s);

  [[nodiscard]] std::int64_t now_ns() const { return now_ns_; }
  [[nodiscard]] Pose2D TruePose() const;  // Map frame.
  [[nodiscard]] Pose2D TruePoseWorld() const { return base_.pose_world(); }
  [[nodiscard]] const World& world() const { return world_; }
  [[nodiscard]] const Rig& rig() const { return rig_; }
  [[nodiscard]] const RobotConfig& robot() const { return robot_; }
  [[nodiscard]] int collision_count() const { return collisions_; }
  // Where person i (World::people order) is now.
  [[nodiscard]] PersonState person_state(std::size_t i) const {
    return PersonAt(world_.people.at(i), clocks_.people_s.at(i));
  }
  // Seconds person i's schedule is behind: time spent waiting for the robot or giving way.
  [[nodiscard]] double person_wait_s(std::size_t i) const {
    return NanosToSeconds(now_ns_) - clocks_.people_s.at(i);
  }
  // Seconds door i's schedule is behind: time it waited to close or open onto the robot.
  [[nodiscard]] double door_wait_s(std::size_t i) const {
    return NanosToSeconds(now_ns_) - clocks_.doors_s.at(i);
  }
  // Seconds furniture i's schedule is behind: time its move waited for the robot.
  [[nodiscard]] double furniture_wait_s(std::size_t i) const {
    return NanosToSeconds(now_ns_) - clocks_.furniture_s.at(i);
  }
  [[nodiscard]] std::uint64_t rays_cast() const;

 private:
  void Step(SimOutput* out);
  // Walks every person on by dt, except those who yield and would come too near the robot
  // standing at `robot_world`.
  void AdvancePeople(double dt_s, const Pose2D& robot_world);
  // Moves the doors' and the furniture's schedules on by dt, except where the next state
  // (a door shut or opened, a chair put down) would overlap the robot at `robot_world`:
  // whoever closes a door or moves a chair waits until the robot has gone.
  void AdvanceDoorsAndFurniture(double dt_s, const Pose2D& robot_world);
  [[nodiscard]] SimFrame Capture(int sensor, std::int64_t capture_ns, const Pose2D& pose_world);

  World world_;
  RobotConfig robot_;
  Rig rig_;
  SimulatorConfig config_;
  DriveBaseModel base_;
  CollisionWorld collision_world_;
  std::unique_ptr<DepthRenderer> renderer_;
  std::int64_t now_ns_ = 0;
  std::int64_t step_ns_;
  std::int64_t next_imu_ns_ = 0;
  std::int64_t next_odometry_ns_ = 0;
  std::uint64_t imu_count_ = 0;
  std::vector<std::int64_t> frame_index_;  // Next frame number per Kinect.
  std::vector<SimFrame> pending_;          // Captured, not yet delivered.
  std::int64_t moving_solids_ns_ = -1;     // Time the renderer's moving geometry shows.
  ScheduleClocks clocks_;                  // Each moving object's own schedule time.
  struct Yielding {
    double waited_s = 0.0;       // Waiting for the robot without a break.
    bool giving_way = false;     // Walking back the way it came.
    double stand_until_s = -1.0; // Stands where it gave way until then.
  };
  std::vector<Yielding> yielding_;
  bool in_contact_ = false;
  int collisions_ = 0;
};

}  // namespace dynamap::robotio::sim
