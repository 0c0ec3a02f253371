// The mapping worker's record of the surfaces seen closely, which the report's surface
// coverage scores against the simulator's true surfaces: marked from where the Kinect
// really was, not from the estimate the frame was mapped at.
#include "dynamap/app/runtime/MappingWorker.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "../robotio/TestPaths.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {
namespace {

// One 160 x 120 frame of the first Kinect of the shipped rig, every pixel at `depth_mm`.
robotio::DepthFrame FlatFrame(const robotio::KinectMount& mount, std::uint16_t depth_mm,
                              std::int64_t stamp_ns) {
  robotio::DepthFrame frame;
  frame.stamp_ns = frame.received_ns = stamp_ns;
  frame.width = 160;
  frame.height = 120;
  frame.intrinsics = mount.intrinsics;
  frame.depth_mm.assign(160 * 120, depth_mm);
  return frame;
}

TEST(MappingWorker, SurfacesCountAsSeenWhereTheKinectReallyLooked) {
  auto rig = robotio::LoadRig(test::Resource("rigs/two_kinects.yaml"));
  ASSERT_TRUE(rig);
  rig->kinects.resize(1);
  rig->kinects[0].intrinsics = rig->kinects[0].intrinsics.Scaled(160, 120);
  const robotio::KinectMount mount = rig->kinects[0];

  // Odometry says the base stands at the start; the simulator has it 0.5 m to the left.
  Mediator mediator(0.0, {});
  std::vector<robotio::OdometryReading> odometry;
  std::vector<robotio::ImuReading> imu;
  for (int ms = 0; ms <= 1000; ms += 10) {
    imu.push_back({robotio::SecondsToNanos(1e-3 * ms), 0.0, 0.0, 0.0});
    if (ms % 20 == 0) odometry.push_back({robotio::SecondsToNanos(1e-3 * ms), 0.0, 0.0});
  }
  mediator.odometry.Add(odometry, imu);
  const robotio::Pose2D truth{0.0, 0.5, 0.0};

  MappingWorkerConfig config;
  config.poses = PoseSource::kOdometry;
  config.area = planning::GridMap(200, 200, 0.05);
  config.area.origin_x_m = config.area.origin_y_m = -5.0;
  MappingWorker worker(mediator, *rig, config);
  std::thread thread([&worker] { worker.Run(); });
  CapturedFrame frame;
  frame.depth = FlatFrame(mount, 1500, robotio::SecondsToNanos(0.5));
  frame.true_pose = truth;
  mediator.frames.Push(frame);
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (mediator.counters.frames_processed.load() < 1 &&
         std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  mediator.control.Stop();
  mediator.frames.Close();
  thread.join();
  ASSERT_EQ(mediator.counters.frames_processed.load(), 1);

  // The image's centre pixel, 1.5 m deep, seen from the true pose and from the estimate.
  const robotio::DepthRays from_truth =
      robotio::DepthToRays(frame.depth, mount, truth.ToIsometry(), 1);
  const robotio::DepthRays from_estimate =
      robotio::DepthToRays(frame.depth, mount, Eigen::Isometry3d::Identity(), 1);
  const std::size_t centre = 60 * 160 + 80;
  ASSERT_EQ(from_truth.ends.size(), 160u * 120u);
  ASSERT_TRUE(from_truth.hit[centre]);
  EXPECT_TRUE(worker.Inspected(from_truth.ends[centre]));
  EXPECT_FALSE(worker.Inspected(from_estimate.ends[centre]));
  // The map itself is the estimate's: the wall went in where odometry placed it.
  const Eigen::Vector3d in_map = from_estimate.ends[centre].cast<double>();
  const octomap::OcTreeKey key = worker.map().tree().coordToKey(in_map.x(), in_map.y(), in_map.z());
  EXPECT_NE(worker.map().tree().search(key), nullptr);
}

}  // namespace
}  // namespace dynamap::app::runtime
