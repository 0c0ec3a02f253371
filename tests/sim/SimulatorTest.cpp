#include <gtest/gtest.h>

#include "SimTestWorlds.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"

namespace dynamap::robotio::sim {
namespace {

Rig SmallRig(double latency_s) {
  Rig rig;
  for (int i = 0; i < 2; ++i) {
    KinectMount m;
    m.id = "kinect" + std::to_string(i);
    m.T_base_kinect = MountPose({0.12, i == 0 ? 0.08 : -0.08, i == 0 ? 0.60 : 0.46},
                                {M_PI, 0.1, i == 0 ? 0.5 : -0.5});
    m.intrinsics = Intrinsics{}.Scaled(80, 60);
    m.latency_s = latency_s;
    rig.kinects.push_back(m);
  }
  return rig;
}

RobotConfig QuietRobot() {
  RobotConfig robot;
  robot.encoder_noise_m_per_sqrt_m = 0.0;
  return robot;
}

SimulatorConfig Config(std::uint64_t seed) {
  SimulatorConfig config;
  config.seed = seed;
  return config;
}

// Motion, collisions and people only: no Kinect frames are rendered.
SimulatorConfig Proprioceptive(std::uint64_t seed) {
  SimulatorConfig config = Config(seed);
  config.render_depth = false;
  return config;
}

TEST(Simulator, FrameShowsThePoseLatencyBeforeDelivery) {
  const World world = testing::MustParse(testing::WallWorldYaml(3.0));
  Simulator simulator(world, QuietRobot(), SmallRig(0.1), Config(3));
  simulator.SetCommand({0, 0.0, 1.0});  // Turning: every instant shows something else.
  SimOutput out = simulator.Advance(1.0);
  ASSERT_GT(out.frames.size(), 10u);
  DepthRenderer reference(world, 1);
  reference.SetMovingSolids({});
  for (const SimFrame& f : out.frames) {
    EXPECT_EQ(f.depth.received_ns - f.depth.stamp_ns, 100'000'000);
    EXPECT_LE(f.depth.received_ns, simulator.now_ns());
  }
  // The frame's content is the render from the ground-truth pose at received - 100 ms.
  const SimFrame& f = out.frames.back();
  const std::int64_t capture = f.depth.received_ns - 100'000'000;
  const StampedPose* before = nullptr;
  const StampedPose* after = nullptr;
  for (const StampedPose& p : out.ground_truth) {
    if (p.stamp_ns <= capture) before = &p;
    if (p.stamp_ns >= capture && after == nullptr) after = &p;
  }
  ASSERT_TRUE(before != nullptr && after != nullptr);
  const double s = after->stamp_ns == before->stamp_ns
                       ? 0.0
                       : static_cast<double>(capture - before->stamp_ns) /
                             static_cast<double>(after->stamp_ns - before->stamp_ns);
  const Pose2D pose = Interpolate(Pose2D::FromIsometry(before->pose), Pose2D::FromIsometry(after->pose), s);
  const KinectMount& mount = simulator.rig().kinects[f.depth.sensor_id];
  KinectModelConfig exact;
  exact.enabled = false;
  const Eigen::Isometry3d T_world_kinect =
      world.robot_start.ToIsometry() * pose.ToIsometry() * mount.T_base_kinect;
  const RenderedImage at_capture = reference.Render(T_world_kinect, mount.intrinsics, 0.5, exact, 0);
  // Compare against the exact render: the delivered depth differs by noise only.
  const Eigen::Isometry3d T_late = world.robot_start.ToIsometry() *
                                   Pose2D::FromIsometry(out.ground_truth.back().pose).ToIsometry() *
                                   mount.T_base_kinect;
  const RenderedImage at_delivery = reference.Render(T_late, mount.intrinsics, 0.5, exact, 0);
  double err_capture = 0.0, err_delivery = 0.0;
  int n = 0;
  for (std::size_t p = 0; p < f.depth.depth_mm.size(); ++p) {
    if (f.depth.depth_mm[p] == 0 || at_capture.depth.depth_mm[p] == 0 ||
        at_delivery.depth.depth_mm[p] == 0) {
      continue;
    }
    err_capture += std::abs(f.depth.depth_mm[p] - at_capture.depth.depth_mm[p]);
    err_delivery += std::abs(f.depth.depth_mm[p] - at_delivery.depth.depth_mm[p]);
    ++n;
  }
  ASSERT_GT(n, 500);
  EXPECT_LT(err_capture / n, 20.0);  // mm: within the noise of a 1-3 m scene.
  EXPECT_GT(err_delivery / n, 2.0 * err_capture / n);
  EXPECT_TRUE(f.T_map_kinect.pose.isApprox(pose.ToIsometry() * mount.T_base_kinect, 1e-6));
}

SimOutput RunFor(std::uint64_t seed, double seconds) {
  World world = testing::MustParse(testing::WallWorldYaml(
      3.0, "people:\n  - {id: walker, path: [{at: [2, -2]}, {at: [2, 2]}]}\n"));
  Simulator simulator(world, RobotConfig{}, SmallRig(0.1), Config(seed));
  simulator.SetCommand({0, 0.3, 0.2});
  SimOutput all = simulator.Advance(seconds);
  return all;
}

TEST(Simulator, SameSeedGivesTheSameRecording) {
  const SimOutput a = RunFor(42, 1.5);
  const SimOutput b = RunFor(42, 1.5);
  const SimOutput c = RunFor(43, 1.5);
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (std::size_t i = 0; i < a.frames.size(); ++i) {
    EXPECT_EQ(a.frames[i].depth.depth_mm, b.frames[i].depth.depth_mm);
    EXPECT_EQ(a.frames[i].labels.labels, b.frames[i].labels.labels);
    EXPECT_EQ(a.frames[i].depth.stamp_ns, b.frames[i].depth.stamp_ns);
  }
  ASSERT_EQ(a.imu.size(), b.imu.size());
  for (std::size_t i = 0; i < a.imu.size(); ++i) EXPECT_EQ(a.imu[i].wz, b.imu[i].wz);
  ASSERT_EQ(a.odometry.size(), b.odometry.size());
  EXPECT_EQ(a.odometry.back().left_m, b.odometry.back().left_m);
  EXPECT_NE(a.frames.back().depth.depth_mm, c.frames.back().depth.depth_mm);
  EXPECT_NE(a.imu.back().wz, c.imu.back().wz);
}

TEST(Simulator, EncoderScaleErrorShowsInOdometry) {
  const World world = testing::MustParse(testing::WallWorldYaml(8.0));
  RobotConfig robot = QuietRobot();
  robot.encoder_scale_error_left = 0.02;
  robot.encoder_scale_error_right = -0.015;
  SimulatorConfig config = Proprioceptive(1);
  Simulator simulator(world, robot, SmallRig(0.1), config);
  simulator.SetCommand({0, 0.5, 0.3});
  SimOutput out = simulator.Advance(4.0);
  ASSERT_FALSE(out.odometry.empty());
  // True wheel travel from the base's pose change: arc of radius v/omega per wheel.
  const Pose2D end = simulator.TruePose();
  EXPECT_GT(end.x, 1.0);
  const double tick = 1.0 / robot.TicksPerMetre();
  const OdometryReading& last = out.odometry.back();
  EXPECT_EQ(last.stamp_ns, 4'000'000'000);
  // left/right true distances: centre distance -/+ heading * half track.
  double centre = 0.0;
  Pose2D prev;
  for (const StampedPose& p : out.ground_truth) {
    const Pose2D q = Pose2D::FromIsometry(p.pose);
    centre += std::hypot(q.x - prev.x, q.y - prev.y);
    prev = q;
  }
  const double heading = end.theta;
  const double true_left = centre - heading * robot.track_width_m / 2.0;
  const double true_right = centre + heading * robot.track_width_m / 2.0;
  EXPECT_NEAR(last.left_m / true_left, 1.02, 2e-4);
  EXPECT_NEAR(last.right_m / true_right, 0.985, 2e-4);
  EXPECT_NEAR(last.left_m, true_left * 1.02, 2e-3 + tick);
}

TEST(Simulator, DrivingIntoAWallIsACollisionWithoutPenetration) {
  const World world = testing::MustParse(testing::WallWorldYaml(2.0));
  SimulatorConfig config = Proprioceptive(1);
  RobotConfig robot;
  Simulator simulator(world, robot, SmallRig(0.1), config);
  simulator.SetCommand({0, 1.0, 0.0});
  SimOutput out = simulator.Advance(6.0);
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(out.collisions[0].object_id, "wall");
  EXPECT_EQ(out.collisions[0].kind, ObjectKind::kWall);
  for (const StampedPose& p : out.ground_truth) {
    EXPECT_LE(p.pose.translation().x() + robot.footprint_radius_m, 2.0 + 1e-9);
  }
  EXPECT_GT(simulator.TruePose().x + robot.footprint_radius_m, 1.95);  // Stopped at the wall.
  // Against the wall it can still turn on the spot (its footprint is a circle).
  const Pose2D stopped = simulator.TruePose();
  simulator.SetCommand({0, 0.0, 1.0});
  (void)simulator.Advance(1.0);
  EXPECT_GT(simulator.TruePose().theta - stopped.theta, 0.5);
  EXPECT_NEAR(simulator.TruePose().x, stopped.x, 1e-9);
  // Pushing on while turning (a path follower turning towards its path) turns it too,
  // without moving it into the wall.
  const Pose2D turned = simulator.TruePose();
  simulator.SetCommand({0, 0.05, -1.0});
  (void)simulator.Advance(2.0);  // The first half second undoes the turn the other way.
  EXPECT_LT(simulator.TruePose().theta - turned.theta, -1.0);
  EXPECT_LE(simulator.TruePose().x + robot.footprint_radius_m, 2.0 + 1e-9);
  // Backing off is allowed.
  simulator.SetCommand({0, -0.5, 0.0});
  (void)simulator.Advance(1.0);
  EXPECT_LT(simulator.TruePose().x, stopped.x - 0.1);
  EXPECT_EQ(simulator.collision_count(), 1);
}

TEST(Simulator, DoorwaysAreAsWideAsTheGapBetweenWallEndsAndCornersAreClosed) {
  // Two collinear walls leave a 0.9 m doorway; the east one turns a corner at x = 5.
  const World world = testing::MustParse(
      "name: doorway\n"
      "floor: {min: [-6, -4], max: [6, 4]}\n"
      "robot_start: {x: 0.45, y: -2, yaw_deg: 90}\n"
      "walls:\n"
      "  - {id: west, from: [-5, 0], to: [0, 0], thickness: 0.12}\n"
      "  - {id: east, from: [0.9, 0], to: [5, 0], thickness: 0.12}\n"
      "  - {id: corner, from: [5, 0], to: [5, 3], thickness: 0.12}\n");
  const Solid west = WallSolid(world, 0);
  const Solid east = WallSolid(world, 1);
  EXPECT_NEAR(west.size.x(), 5.0, 1e-9);          // Both ends free.
  EXPECT_NEAR(east.size.x(), 4.1 + 0.06, 1e-9);   // Overlaps the corner wall only.
  EXPECT_NEAR(east.pose.x, (0.9 + 5.06) / 2.0, 1e-9);
  const CollisionWorld collisions(world, 1.0);
  // A 0.3 m footprint in the middle of the doorway has 0.15 m on either side.
  EXPECT_NEAR(collisions.Check({0.45, 0.0}, 0.3, 0.0).clearance_m, 0.15, 1e-9);
  // The corner is closed: the outside of the joint is wall.
  EXPECT_LT(collisions.Check({5.04, -0.04}, 0.001, 0.0).clearance_m, 0.0);
}

// A person whose path runs through the standing robot: x from 3 m to -3 m along y = 0.
std::string WalkerThroughTheRobot(const std::string& yields) {
  return testing::WallWorldYaml(
      8.0, "people:\n  - {id: walker, speed: 1.0, loop: false, " + yields +
               "path: [{at: [3.0, 0.0]}, {at: [-3.0, 0.0]}]}\n");
}

TEST(Simulator, PeopleWaitForTheRobotInsteadOfWalkingIntoIt) {
  const World world = testing::MustParse(WalkerThroughTheRobot(""));
  SimulatorConfig config = Proprioceptive(2);
  const RobotConfig robot;
  Simulator simulator(world, robot, SmallRig(0.1), config);
  (void)simulator.Advance(4.0);
  EXPECT_EQ(simulator.collision_count(), 0);
  // It stopped at the yield clearance, about 2.1 s into its 6 s walk.
  const double stop_distance = robot.footprint_radius_m + 0.25 + config.yield_clearance_m;
  EXPECT_NEAR(simulator.person_state(0).position.x(), stop_distance, 0.01);
  EXPECT_NEAR(simulator.person_wait_s(0), 4.0 - (3.0 - stop_distance), 0.05);
  // The robot drives towards the person: it backs off the way it came, no contact.
  simulator.SetCommand({0, 0.3, 0.0});
  (void)simulator.Advance(1.0);
  simulator.SetCommand({0, 0.0, 0.0});
  (void)simulator.Advance(0.5);
  EXPECT_EQ(simulator.collision_count(), 0);
  const double gap = simulator.person_state(0).position.x() - simulator.TruePose().x;
  EXPECT_NEAR(gap, stop_distance, 0.02);
  EXPECT_GT(simulator.person_state(0).position.x(), stop_distance + 0.1);
}

TEST(Simulator, APersonGivesWayToARobotThatStaysInItsWayThenWalksOn) {
  const World world = testing::MustParse(WalkerThroughTheRobot(""));
  SimulatorConfig config = Proprioceptive(2);
  const RobotConfig robot;
  Simulator simulator(world, robot, SmallRig(0.1), config);
  // Waits 5 s, then walks back until 1.5 m from the robot's footprint, and stands there.
  (void)simulator.Advance(10.0);
  const double give_way = robot.footprint_radius_m + 0.25 + config.give_way_clearance_m;
  EXPECT_NEAR(simulator.person_state(0).position.x(), give_way, 0.02);
  // The robot leaves the person's way (drives 2 m along +y); the person walks on past
  // where the robot stood, to the end of its path.
  simulator.SetCommand({0, 0.0, 1.5});
  (void)simulator.Advance(1.05);
  simulator.SetCommand({0, 0.8, 0.0});
  (void)simulator.Advance(2.5);
  simulator.SetCommand({0, 0.0, 0.0});
  (void)simulator.Advance(15.0);
  EXPECT_NEAR(simulator.person_state(0).position.x(), -3.0, 1e-6);
  EXPECT_EQ(simulator.collision_count(), 0);
}

TEST(Simulator, APersonWhoDoesNotYieldWalksIntoTheStandingRobot) {
  const World world = testing::MustParse(WalkerThroughTheRobot("yields: false, "));
  SimulatorConfig config = Proprioceptive(2);
  Simulator simulator(world, RobotConfig{}, SmallRig(0.1), config);
  const SimOutput out = simulator.Advance(6.0);
  ASSERT_EQ(out.collisions.size(), 1u);
  EXPECT_EQ(out.collisions[0].object_id, "walker");
  EXPECT_EQ(out.collisions[0].kind, ObjectKind::kPerson);
  EXPECT_NEAR(simulator.person_wait_s(0), 0.0, 1e-9);
}

TEST(Simulator, ADoorIsNotShutOntoTheRobotStandingInItsDoorway) {
  // The door's closed leaf runs through the robot's centre (x = 0); it is due to close at
  // 1 s. Whoever shuts it waits until the robot has driven out of the doorway.
  const World world = testing::MustParse(testing::WallWorldYaml(
      8.0, "doors:\n  - {id: door, hinge: [0, -0.45], width: 0.9, closed_yaw_deg: 90, "
           "open_yaw_deg: 180, open: true, schedule: [{t: 1, open: false}]}\n"));
  Simulator simulator(world, RobotConfig{}, SmallRig(0.1), Proprioceptive(2));
  (void)simulator.Advance(3.0);
  EXPECT_EQ(simulator.collision_count(), 0);
  EXPECT_NEAR(simulator.door_wait_s(0), 2.0, 0.01);
  simulator.SetCommand({0, 0.5, 0.0});
  (void)simulator.Advance(2.0);
  simulator.SetCommand({0, 0.0, 0.0});
  (void)simulator.Advance(1.0);
  EXPECT_EQ(simulator.collision_count(), 0);
  // It closed once the footprint was 0.1 m clear of the closed leaf, about 1 s later.
  const double waited = simulator.door_wait_s(0);
  EXPECT_GT(waited, 2.5);
  EXPECT_LT(waited, 4.0);
  EXPECT_FALSE(DoorOpenAt(world.doors[0], NanosToSeconds(simulator.now_ns()) - waited));
}

TEST(Simulator, AChairIsNotPutDownWhereTheRobotStands) {
  // A chair due at 1 s to be moved to 0.3 m in front of the robot's centre.
  const World world = testing::MustParse(testing::WallWorldYaml(
      8.0, "furniture:\n  - {id: chair, pose: [3.0, 2.0, 0], size: [0.5, 0.5, 1.0], "
           "moves: [{t: 1, pose: [0.3, 0.0, 0]}]}\n"));
  Simulator simulator(world, RobotConfig{}, SmallRig(0.1), Proprioceptive(2));
  (void)simulator.Advance(2.0);
  EXPECT_EQ(simulator.collision_count(), 0);
  EXPECT_NEAR(simulator.furniture_wait_s(0), 1.0, 0.01);
  simulator.SetCommand({0, -0.5, 0.0});  // The robot backs away from where it goes ...
  (void)simulator.Advance(2.0);
  simulator.SetCommand({0, 0.0, 0.0});
  (void)simulator.Advance(1.0);
  EXPECT_EQ(simulator.collision_count(), 0);
  // ... and it is put down once the footprint is 0.1 m clear of it (robot x < -0.41 m).
  EXPECT_GT(simulator.furniture_wait_s(0), 1.5);
  EXPECT_LT(simulator.furniture_wait_s(0), 3.5);
  EXPECT_LT(simulator.TruePose().x, -0.5);
}

TEST(Simulator, PeopleAreLabelledDynamicAndMovedChairsOnlyBeforeTheirMove) {
  World world = testing::MustParse(testing::WallWorldYaml(
      4.0,
      "duration_s: 10\n"
      "people:\n  - {id: walker, path: [{at: [2.0, 0.4]}]}\n"
      "furniture:\n  - {id: chair, pose: [2.0, -0.6, 0], size: [0.5, 0.5, 1.0], "
      "moves: [{t: 5, pose: [2.0, -1.0, 0]}]}\n"));
  Rig rig;
  KinectMount m;
  m.T_base_kinect = MountPose({0, 0, 0.6}, {M_PI, 0.05, 0});
  m.intrinsics = Intrinsics{}.Scaled(160, 120);
  rig.kinects.push_back(m);
  SimulatorConfig config = Config(5);
  config.kinect.random_dropout_probability = 0.0;
  Simulator simulator(world, RobotConfig{}, rig, config);
  const int walker = world.FindObject("walker");
  const int chair = world.FindObject("chair");
  const int wall = world.FindObject("wall");
  auto count = [&](const LabelFrame& labels, int object, bool dynamic) {
    int n = 0;
    for (std::uint16_t l : labels.labels) {
      if (l != 0 && LabelFrame::ObjectIndex(l) == object && LabelFrame::IsDynamic(l) == dynamic) ++n;
    }
    return n;
  };
  SimOutput early = simulator.AdvanceTo(1'000'000'000);
  ASSERT_FALSE(early.frames.empty());
  const LabelFrame& first = early.frames.back().labels;
  EXPECT_GT(count(first, walker, true), 50);
  EXPECT_EQ(count(first, walker, false), 0);
  EXPECT_GT(count(first, chair, true), 20);   // Leaves this placement at t = 5 s.
  EXPECT_GT(count(first, wall, false), 100);
  EXPECT_EQ(count(first, wall, true), 0);
  SimOutput late = simulator.AdvanceTo(7'000'000'000);
  const LabelFrame& last = late.frames.back().labels;
  EXPECT_GT(count(last, walker, true), 50);
  EXPECT_GT(count(last, chair, false), 20);   // Its final placement: static.
  EXPECT_EQ(count(last, chair, true), 0);
}

}  // namespace
}  // namespace dynamap::robotio::sim
