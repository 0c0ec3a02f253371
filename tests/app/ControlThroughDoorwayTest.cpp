// The control worker against the simulator: a base whose map pose is 0.12 m off (as SLAM's
// was at a mission's door contacts) follows a path through the middle of a 0.9 m doorway,
// as the map has it. With what its Kinects saw kept in the odometry frame and the path
// shifted off it, the footprint clears the door posts; without, it touches one; and it
// still does after standing in the doorway, where it cannot see the posts. The map guard
// checks the planner's grid on the way.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "../robotio/TestPaths.hpp"
#include "dynamap/app/runtime/ControlWorker.hpp"
#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app::runtime {
namespace {

// A wall across the way, 0.12 m thick, with a doorway 2 m east of the robot's start.
std::string DoorwayWorld(double width) {
  const double half = 0.5 * width;
  return "name: doorway\n"
         "floor: {min: [0, 0], max: [6, 4]}\n"
         "robot_start: {x: 1.0, y: 2.0, yaw_deg: 0}\n"
         "walls:\n"
         "  - {id: post_south, from: [3, 0], to: [3, " + std::to_string(2.0 - half) +
         "], thickness: 0.12, height: 2.5}\n"
         "  - {id: post_north, from: [3, " + std::to_string(2.0 + half) +
         "], to: [3, 4], thickness: 0.12, height: 2.5}\n";
}

// The same wall on the planner's grid (map frame: the start), 5 cm cells; the posts
// mapped `north_narrower_m` and `south_narrower_m` into the doorway (a door leaf mapped a
// cell thicker).
std::shared_ptr<const planning::GridMap> DoorwayGrid(double width, double north_narrower_m,
                                                     double south_narrower_m) {
  auto map = std::make_shared<planning::GridMap>(120, 80, 0.05);
  map->origin_x_m = -1.0;
  map->origin_y_m = -2.0;
  for (int y = 0; y < map->height; ++y) {
    for (int x = 0; x < map->width; ++x) {
      const double cx = map->CenterX(x);
      const double cy = map->CenterY(y);
      const bool wall = std::abs(cx - 2.0) <= 0.06 &&
                        (cy <= -0.5 * width + south_narrower_m ||
                         cy >= 0.5 * width - north_narrower_m);
      map->Set({x, y}, wall ? planning::CellState::kObstacle : planning::CellState::kNavigable);
    }
  }
  return map;
}
struct Passage {
  int collisions = 0;
  double end_x_m = 0.0;   // True map x at the end (the doorway is at 2 m).
  double max_shift_m = 0.0;
  std::int64_t map_guard_stops = 0;
  double stopped_in_doorway_x_m = 0.0;  // True map x where it stopped to wait (0: did not).
};

// The base drives a path `path_y_m` north of the middle of a doorway `width` wide, as the
// map has it, with its map pose `map_error_m` north of the truth (negative: south); a
// `squeezed` plan is one FindSqueezePath made. With `wait_in_doorway_s`, the first plan
// ends in the doorway's middle and the way on is planned that long after the base got
// there; the memory keeps what no Kinect can see up to `keep_hidden_s`.
Passage DriveThroughTheDoorway(bool shift_path, double width, double map_error_m,
                               double path_y_m = 0.0, double north_narrower_m = 0.0,
                               double south_narrower_m = 0.0, bool squeezed = false,
                               double wait_in_doorway_s = 0.0, double keep_hidden_s = 60.0) {
  auto world = robotio::sim::ParseWorld(DoorwayWorld(width), "doorway.yaml");
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
  config.memory.keep_hidden_s = keep_hidden_s;
  ControlWorker control(mediator, *rig, config);
  Plan plan;  // On the map, where the doorway's middle is on the start's line.
  plan.has_goal = true;
  plan.goal_map = {4.0, path_y_m};
  plan.path_map = {{0.0, path_y_m}, {4.0, path_y_m}};
  plan.map = DoorwayGrid(width, north_narrower_m, south_narrower_m);  // The map guard checks it.
  plan.squeezed = squeezed;
  Plan to_doorway = plan;
  to_doorway.goal_map = {2.0, path_y_m};
  to_doorway.path_map = {{0.0, path_y_m}, {2.0, path_y_m}};
  bool wait = wait_in_doorway_s > 0.0;
  mediator.plan.Set(wait ? to_doorway : plan);
  std::int64_t in_doorway_ns = -1;  // When the base stopped in the doorway.

  const Eigen::Vector2d map_error(0.0, map_error_m);  // Map pose minus truth.
  Passage passage;
  const double dt = 0.05;
  const int steps = 400 + static_cast<int>(std::ceil((wait_in_doorway_s + 10.0) / dt));
  for (int i = 1; i <= steps; ++i) {
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
    const robotio::VelocityCommand command = control.Tick(now, dt);
    sim.SetCommand(command);
    if (wait && in_doorway_ns < 0 && truth.x > 1.7 && std::abs(command.v) < 1e-3) {
      in_doorway_ns = now;
      passage.stopped_in_doorway_x_m = truth.x;
    }
    if (wait && in_doorway_ns >= 0 &&
        now - in_doorway_ns >= robotio::SecondsToNanos(wait_in_doorway_s)) {
      mediator.plan.Set(plan);
      wait = false;
    }
    passage.max_shift_m = std::max(passage.max_shift_m, control.path_shift().norm());
    if (truth.x > 3.2) break;
  }
  passage.collisions = sim.collision_count();
  passage.map_guard_stops = mediator.counters.map_guard_stops.load();
  passage.end_x_m = sim.TruePose().x;
  return passage;
}

TEST(ControlThroughDoorway, AMapPoseOffByADecimetreTouchesADoorPostUnlessThePathIsShifted) {
  const Passage unshifted = DriveThroughTheDoorway(false, 0.9, -0.12);
  EXPECT_GE(unshifted.collisions, 1);
  EXPECT_EQ(unshifted.max_shift_m, 0.0);
  const Passage shifted = DriveThroughTheDoorway(true, 0.9, -0.12);
  EXPECT_EQ(shifted.collisions, 0);
  EXPECT_GT(shifted.end_x_m, 3.2) << "did not get through";
  EXPECT_GT(shifted.max_shift_m, 0.07);
  EXPECT_LT(shifted.max_shift_m, 0.17);
}

TEST(ControlThroughDoorway, WithTheTruePoseATightDoorwayIsPassedWithoutShifting) {
  // 0.8 m: 4 cm a side, less than the shift's comfort distance, and no shift gains any.
  const Passage tight = DriveThroughTheDoorway(true, 0.8, 0.0);
  EXPECT_EQ(tight.collisions, 0);
  EXPECT_GT(tight.end_x_m, 3.2) << "did not get through";
  EXPECT_LT(tight.max_shift_m, 0.03);
}

TEST(ControlThroughDoorway, WithTheTruePoseAPathTooNearAPostIsShiftedOffItAndPassed) {
  // The map has the north post a cell into the doorway and the squeeze path runs 0.1 m
  // north of the middle, 1 cm inside the footprint at the real post: the shift moves the
  // base off it and the base gets through with the map guard on the way. (The guard's
  // rule of holding only when both poses run into the map is not what lets it through
  // here: it passed with the guard on the shifted pose alone too.)
  const Passage off_centre = DriveThroughTheDoorway(true, 0.9, 0.0, 0.1, 0.05);
  EXPECT_EQ(off_centre.collisions, 0);
  EXPECT_GT(off_centre.end_x_m, 3.2) << "did not get through";
  EXPECT_GT(off_centre.max_shift_m, 0.01);
}

TEST(ControlThroughDoorway, OnASqueezedPathTheMapGuardAllowsTheSqueezeRadius) {
  // The posts' obstacle cells centred at 0.375 and -0.325 m, the path 0.34 m from the
  // north one and 0.36 m from the south one: no cell left at the full radius (0.36 m),
  // so the planner squeezes (0.335 m). With the full footprint the map guard holds the
  // base as it nears the north post's cell (here it turns a little while held and gets
  // through; office seed 2, held with nothing to turn, stood 660 s in front of N2's door).
  // Measured with the squeeze's footprint, nothing holds it, and the real 0.9 m is passed.
  const Passage full = DriveThroughTheDoorway(false, 0.9, 0.0, 0.035, 0.1, 0.15, false);
  EXPECT_GT(full.map_guard_stops, 0);
  const Passage squeezed = DriveThroughTheDoorway(false, 0.9, 0.0, 0.035, 0.1, 0.15, true);
  EXPECT_EQ(squeezed.map_guard_stops, 0);
  EXPECT_EQ(squeezed.collisions, 0);
  EXPECT_GT(squeezed.end_x_m, 3.2) << "did not get through";
}

TEST(ControlThroughDoorway, WaitingInTheDoorwayTheBaseKeepsThePostsItCannotSee) {
  // The base stops in a 0.9 m doorway with its map pose 0.2 m off and stands there 15 s:
  // the posts beside it are nearer than the Kinects' 0.5 m and out of their view. Forgotten
  // after the memory's 8 s, the shift goes with them and the base, moving on, touches a
  // post (office seed 2 touched one seven times so); kept while unseen, it passes.
  const Passage forgotten =
      DriveThroughTheDoorway(true, 0.9, -0.2, 0.0, 0.0, 0.0, false, 15.0, 0.0);
  EXPECT_NEAR(forgotten.stopped_in_doorway_x_m, 1.85, 0.1);
  EXPECT_GE(forgotten.collisions, 1);
  const Passage kept = DriveThroughTheDoorway(true, 0.9, -0.2, 0.0, 0.0, 0.0, false, 15.0);
  EXPECT_NEAR(kept.stopped_in_doorway_x_m, 1.85, 0.1);
  EXPECT_EQ(kept.collisions, 0);
  EXPECT_GT(kept.end_x_m, 3.2) << "did not get through";
  EXPECT_GT(kept.max_shift_m, 0.15);
}

}  // namespace
}  // namespace dynamap::app::runtime
