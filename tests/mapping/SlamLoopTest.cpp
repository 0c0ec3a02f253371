#include "dynamap/mapping/SlamLoop.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "dynamap/mapping/MotionModel.hpp"
#include "dynamap/mapping/TrajectoryEvaluation.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::mapping {
namespace {

std::string Resource(const std::string& relative) {
  return std::string(DYNAMAP_RESOURCES_DIR) + "/" + relative;
}

TEST(SlamLoop, GroupsOneFramePerSensorIntoScans) {
  const auto scans = GroupIntoScans({0, 10, 33, 40, 66, 70, 71}, {0, 1, 0, 1, 0, 0, 1}, 20);
  ASSERT_EQ(scans.size(), 4u);
  EXPECT_EQ(scans[0], (std::vector<std::size_t>{0, 1}));
  EXPECT_EQ(scans[1], (std::vector<std::size_t>{2, 3}));
  EXPECT_EQ(scans[2], (std::vector<std::size_t>{4}));
  EXPECT_EQ(scans[3], (std::vector<std::size_t>{5, 6}));
}

// A short drive through the simulated office at low Kinect resolution: SLAM with the
// default settings must end closer to the truth than odometry + gyro alone.
TEST(SlamLoop, ReducedOfficeDriveBeatsOdometry) {
  auto world = robotio::sim::LoadWorld(Resource("worlds/office.yaml"));
  ASSERT_TRUE(world.ok()) << world.error().message;
  auto robot = robotio::sim::LoadRobotConfig(Resource("robots/segway_rmp50.yaml"));
  ASSERT_TRUE(robot.ok()) << robot.error().message;
  auto rig = robotio::LoadRig(Resource("rigs/two_kinects.yaml"));
  ASSERT_TRUE(rig.ok()) << rig.error().message;
  for (auto& mount : rig->kinects) {
    mount.intrinsics = mount.intrinsics.Scaled(160, 120);
    mount.rate_hz = 10.0;
  }
  // Odometry errors well above the simulator's defaults, so the test shows a difference.
  robot->encoder_scale_error_left = 0.03;
  robot->encoder_scale_error_right = -0.03;
  robot->gyro_bias_radps = 0.01;
  robotio::sim::SimulatorConfig sim_config;
  sim_config.seed = 7;
  robotio::sim::Simulator sim(*world, *robot, *rig, sim_config);

  std::vector<robotio::OdometryReading> odometry;
  std::vector<robotio::ImuReading> imu;
  std::vector<robotio::DepthFrame> frames;
  robotio::Trajectory truth;
  auto take = [&](robotio::sim::SimOutput out) {
    odometry.insert(odometry.end(), out.odometry.begin(), out.odometry.end());
    imu.insert(imu.end(), out.imu.begin(), out.imu.end());
    truth.insert(truth.end(), out.ground_truth.begin(), out.ground_truth.end());
    for (auto& f : out.frames) frames.push_back(std::move(f.depth));
  };
  // Straight, a turn, straight again.
  const double phases[][3] = {{0.4, 0.0, 5.0}, {0.2, 0.5, 3.0}, {0.4, 0.0, 4.0}};
  for (const auto& [v, omega, seconds] : phases) {
    sim.SetCommand({sim.now_ns(), v, omega});
    take(sim.Advance(seconds));
  }
  take(sim.Advance(0.3));  // Deliver the last frames.
  ASSERT_GT(frames.size(), 100u);

  std::sort(frames.begin(), frames.end(),
            [](const auto& a, const auto& b) { return a.stamp_ns < b.stamp_ns; });
  std::vector<std::int64_t> stamps;
  std::vector<int> sensors;
  for (const auto& f : frames) {
    stamps.push_back(f.stamp_ns);
    sensors.push_back(f.sensor_id);
  }
  const Trajectory2D dead_reckoning = DeadReckon(odometry, imu, {});
  MappingConfig mapping;
  mapping.resolution_m = 0.1;
  mapping.voxel_filter_m = 0.1;
  SlamConfig slam_config;
  SlamLoop slam(slam_config, mapping, *rig);
  robotio::Trajectory estimate;
  robotio::Trajectory odometry_only;
  std::size_t accepted = 0;
  for (const auto& scan : GroupIntoScans(stamps, sensors, 60'000'000)) {
    std::vector<robotio::DepthFrame> group;
    std::vector<robotio::Pose2D> odometry_poses;
    for (std::size_t i : scan) {
      group.push_back(frames[i]);
      odometry_poses.push_back(PoseAt(dead_reckoning, frames[i].stamp_ns));
    }
    const SlamStep step = slam.ProcessScan(group, odometry_poses);
    accepted += step.accepted ? 1 : 0;
    estimate.push_back(robotio::ToStampedPose(group.front().stamp_ns, step.pose));
    odometry_only.push_back(robotio::ToStampedPose(group.front().stamp_ns, odometry_poses.front()));
  }
  // Both estimates start at the odometry origin = the map origin = the true start pose.
  const auto slam_error = EvaluateTrajectory(truth, estimate, {});
  const auto odometry_error = EvaluateTrajectory(truth, odometry_only, {});
  ASSERT_TRUE(slam_error && odometry_error);
  EXPECT_GT(accepted, estimate.size() / 10);
  EXPECT_LT(slam_error->ate_m.rmse, odometry_error->ate_m.rmse);
  RecordProperty("slam_ate_m", std::to_string(slam_error->ate_m.rmse));
  RecordProperty("odometry_ate_m", std::to_string(odometry_error->ate_m.rmse));
  std::printf("SLAM ATE %.4f m, odometry ATE %.4f m, %zu/%zu accepted\n",
              slam_error->ate_m.rmse, odometry_error->ate_m.rmse, accepted, estimate.size());
}

}  // namespace
}  // namespace dynamap::mapping
