// The control worker against the simulator: a base whose map pose is 0.12 m off (as SLAM's
// was at a mission's door contacts) follows a path through the middle of a 0.9 m doorway,
// as the map has it. With what its Kinects saw kept in the odometry frame and the path
// shifted off it, the footprint clears the door posts; without, it touches one.
#include <gtest/gtest.h>

#include "../robotio/TestPaths.hpp"
#include "dynamap/app/runtime/ControlWorker.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app::runtime {
namespace {

// A wall across the way, 0.12 m thick, with a 0.9 m doorway 2 m east of the robot's start.
constexpr const char* kDoorway = R"(
name: doorway
floor: {min: [0, 0], max: [6, 4]}
robot_start: {x: 1.0, y: 2.0, yaw_deg: 0}
walls:
  - {id: post_south, from: [3, 0], to: [3, 1.55], thickness: 0.12, height: 2.5}
  - {id: post_north, from: [3, 2.45], to: [3, 4], thickness: 0.12, height: 2.5}
)";

struct Passage {
  int collisions = 0;
  double end_x_m = 0.0;   // True map x at the end (the doorway is at 2 m).
  double max_shift_m = 0.0;
};

Passage DriveThroughTheDoorway(bool shift_path) {
  auto world = robotio::sim::ParseWorld(kDoorway, "doorway.yaml");
  auto rig = robotio::LoadRig(test::Resource("rigs/two_kinects.yaml"));
  auto robot = robotio::sim::LoadRobotConfig(test::Resource("robots/segway_rmp50.yaml"));
  EXPECT_TRUE(world && rig && robot);
  if (!world || !rig || !robot) return {};
  for (robotio::KinectMount& mount : rig->kinects) {
    mount.intrinsics = mount.intrinsics.Scaled(160, 120);
  }
  robotio::sim::SimulatorConfig sim_config;
  sim_config.render_threads = 1;
  robotio::sim::Simulator sim(*world, *robot, *rig, sim_config);

  Mediator mediator(0.0, {});
  ControlWorkerConfig config;
  config.initial_still_s = 0.0;
  config.initial_turn_rad = 0.0;
  config.path_shift.enabled = shift_path;
  ControlWorker control(mediator, *rig, config);
  Plan plan;  // On the map, where the doorway's middle is on the start's line.
  plan.has_goal = true;
  plan.goal_map = {4.0, 0.0};
  plan.path_map = {{0.0, 0.0}, {4.0, 0.0}};
  mediator.plan.Set(plan);

  const Eigen::Vector2d map_error(0.0, -0.12);  // Map pose minus truth.
  Passage passage;
  const double dt = 0.05;
  for (int i = 1; i <= 400; ++i) {
    const std::int64_t now = robotio::SecondsToNanos(i * dt);
    const robotio::sim::SimOutput out = sim.AdvanceTo(now);
    mediator.odometry.Add(out.odometry, out.imu);
    for (const robotio::sim::SimFrame& frame : out.frames) {
      mediator.latest_depth[frame.depth.sensor_id].Set(frame.depth);
    }
    const auto odom = mediator.odometry.Latest();
    if (!odom) continue;
    const robotio::Pose2D truth = sim.TruePose();
    mediator.pose_fix.Set(
        {now, {truth.x + map_error.x(), truth.y + map_error.y(), truth.theta}, odom->pose});
    sim.SetCommand(control.Tick(now, dt));
    passage.max_shift_m = std::max(passage.max_shift_m, control.path_shift().norm());
    if (truth.x > 3.2) break;
  }
  passage.collisions = sim.collision_count();
  passage.end_x_m = sim.TruePose().x;
  return passage;
}

TEST(ControlThroughDoorway, AMapPoseOffByADecimetreTouchesADoorPostUnlessThePathIsShifted) {
  const Passage unshifted = DriveThroughTheDoorway(false);
  EXPECT_GE(unshifted.collisions, 1);
  EXPECT_EQ(unshifted.max_shift_m, 0.0);
  const Passage shifted = DriveThroughTheDoorway(true);
  EXPECT_EQ(shifted.collisions, 0);
  EXPECT_GT(shifted.end_x_m, 3.2) << "did not get through";
  EXPECT_NEAR(shifted.max_shift_m, 0.12, 0.05);
}

}  // namespace
}  // namespace dynamap::app::runtime
