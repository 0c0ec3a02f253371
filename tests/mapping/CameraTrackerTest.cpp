// Registration-only tracking of a free camera: on views made from a real Kinect frame
// (TUM RGB-D) and on a simulated hand-held walk through an office room.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "../support/ReprojectedView.hpp"
#include "dynamap/mapping/CameraTracker.hpp"
#include "dynamap/robotio/DepthImageIo.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/sim/DepthRenderer.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::mapping {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr std::int64_t kFrameNs = 33'333'333;

double Degrees(double rad) { return rad * 180.0 / kPi; }
double Radians(double deg) { return deg * kPi / 180.0; }

// One forward-looking camera whose body frame is the tracked "base".
robotio::Rig LevelCameraRig(const robotio::Intrinsics& intrinsics, double max_range_m) {
  robotio::KinectMount mount;
  mount.id = "camera";
  mount.T_base_kinect = robotio::MountPose(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  mount.intrinsics = intrinsics;
  mount.min_range_m = 0.4;
  mount.max_range_m = max_range_m;
  mount.latency_s = 0.0;
  robotio::Rig rig;
  rig.kinects.push_back(mount);
  return rig;
}

Eigen::Isometry3d BodyPose(const Eigen::Vector3d& position, double roll, double pitch, double yaw) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  pose.translation() = position;
  return pose;
}

double AngleBetween(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd((a.inverse() * b).rotation()).angle();
}

robotio::DepthFrame RealTumFrame() {
  auto image = robotio::ReadDepthImage(std::string(DYNAMAP_SHARED_DATA_DIR) + "/tum/TUM_depth.png");
  EXPECT_TRUE(image.ok()) << image.error().message;
  robotio::DepthFrame frame;
  if (!image.ok()) return frame;
  frame.width = image->width;
  frame.height = image->height;
  frame.depth_mm = robotio::TumToMillimetres(image->values);
  return frame;
}

TEST(CameraTracker, FollowsViewsOfARealKinectFrame) {
  const robotio::DepthFrame real = RealTumFrame();
  ASSERT_TRUE(real.Valid());
  const robotio::Rig rig = LevelCameraRig(real.intrinsics, 4.0);
  const Eigen::Isometry3d mount = rig.kinects[0].T_base_kinect;
  // Per frame: 1 cm forward, 0.5 cm left, 0.3 cm up, 0.5° yaw, 0.3° pitch.
  const Eigen::Isometry3d step = BodyPose({0.01, 0.005, 0.003}, 0.0, Radians(0.3), Radians(0.5));
  CameraTracker tracker({}, rig);
  Eigen::Isometry3d truth = Eigen::Isometry3d::Identity();
  int accepted = 0;
  for (int k = 0; k < 8; ++k) {
    robotio::DepthFrame frame = test::ReprojectedView(real, mount.inverse() * truth * mount);
    frame.stamp_ns = k * kFrameNs;
    const TrackerStep result = tracker.Track({frame});
    if (result.accepted) ++accepted;
    EXPECT_LT((result.pose.translation() - truth.translation()).norm(), 0.01) << "frame " << k;
    EXPECT_LT(Degrees(AngleBetween(result.pose, truth)), 0.3) << "frame " << k;
    truth = truth * step;
  }
  EXPECT_EQ(accepted, 7);  // Every frame after the first.
}

TEST(CameraTracker, KeepsThePredictionWhenTheScanDoesNotFit) {
  const robotio::DepthFrame real = RealTumFrame();
  ASSERT_TRUE(real.Valid());
  const robotio::Rig rig = LevelCameraRig(real.intrinsics, 4.0);
  CameraTracker tracker({}, rig);
  robotio::DepthFrame first = real;
  ASSERT_TRUE(tracker.Track({first}).keyframe);
  // A frame of something else: a flat wall 1 m away fits the room nowhere.
  robotio::DepthFrame wall = real;
  std::fill(wall.depth_mm.begin(), wall.depth_mm.end(), std::uint16_t{1000});
  wall.stamp_ns = kFrameNs;
  const TrackerStep step = tracker.Track({wall});
  EXPECT_TRUE(step.registered);
  EXPECT_FALSE(step.accepted);
  EXPECT_FALSE(step.keyframe);
  EXPECT_TRUE(step.pose.isApprox(step.predicted));
}

TEST(CameraTracker, RestartsItsLocalMapWhenTheTrackIsLost) {
  const robotio::DepthFrame real = RealTumFrame();
  ASSERT_TRUE(real.Valid());
  CameraTrackerConfig config;
  config.restart_after_rejections = 3;
  CameraTracker tracker(config, LevelCameraRig(real.intrinsics, 4.0));
  (void)tracker.Track({real});
  robotio::DepthFrame wall = real;
  std::fill(wall.depth_mm.begin(), wall.depth_mm.end(), std::uint16_t{1000});
  bool restarted = false;
  for (int k = 1; k <= 3; ++k) {
    wall.stamp_ns = k * kFrameNs;
    restarted = tracker.Track({wall}).restarted;
  }
  EXPECT_TRUE(restarted);
  EXPECT_EQ(tracker.restarts(), 1u);
  EXPECT_EQ(tracker.keyframes(), 2u);  // The wall is the new local map.
}

// A hand-held camera carried 2.9 m through office room N1 at 1.2–1.3 m towards its west
// wall, shelf and desks (yaw sweeping 70°, pitch and height bobbing), Kinect noise on,
// 320 × 240 at 30 Hz.
TEST(CameraTracker, TracksAHandHeldWalkThroughASimulatedRoom) {
  auto world = robotio::sim::LoadWorld(std::string(DYNAMAP_RESOURCES_DIR) + "/worlds/office.yaml");
  ASSERT_TRUE(world.ok()) << world.error().message;
  const robotio::Intrinsics intrinsics = robotio::Intrinsics{}.Scaled(320, 240);
  const robotio::Rig rig = LevelCameraRig(intrinsics, 4.5);
  const Eigen::Isometry3d mount = rig.kinects[0].T_base_kinect;
  robotio::sim::DepthRenderer renderer(*world, 2);
  const robotio::sim::KinectModelConfig noise;
  CameraTracker tracker({}, rig);
  constexpr int kFrames = 120;
  Eigen::Isometry3d start = Eigen::Isometry3d::Identity();
  double squared_error = 0.0;
  double worst_angle_deg = 0.0;
  int accepted = 0;
  Eigen::Isometry3d last_error = Eigen::Isometry3d::Identity();
  for (int k = 0; k < kFrames; ++k) {
    const double s = static_cast<double>(k) / (kFrames - 1);
    const double t = k / 30.0;
    const Eigen::Isometry3d body =
        BodyPose({3.0 - 1.0 * s, 11.5 + 1.5 * s, 1.25 + 0.03 * std::sin(2.0 * kPi * 1.5 * t)},
                 Radians(2.0) * std::sin(2.0 * kPi * 0.7 * t),
                 Radians(10.0 + 5.0 * std::sin(2.0 * kPi * 0.5 * t)),
                 Radians(150.0 - 50.0 * s));
    if (k == 0) start = body;
    auto image = renderer.Render(body * mount, intrinsics, 0.4, noise, static_cast<std::uint64_t>(k));
    image.depth.stamp_ns = k * kFrameNs;
    const TrackerStep step = tracker.Track({image.depth});
    if (step.accepted) ++accepted;
    const Eigen::Isometry3d truth = start.inverse() * body;
    squared_error += (step.pose.translation() - truth.translation()).squaredNorm();
    worst_angle_deg = std::max(worst_angle_deg, Degrees(AngleBetween(step.pose, truth)));
    last_error = truth.inverse() * step.pose;
  }
  const double ate = std::sqrt(squared_error / kFrames);
  std::printf("hand-held walk: ATE %.4f m, end error %.4f m, worst %.2f deg, %d accepted, "
              "%zu keyframes\n",
              ate, last_error.translation().norm(), worst_angle_deg, accepted, tracker.keyframes());
  EXPECT_LT(ate, 0.03);
  EXPECT_LT(last_error.translation().norm(), 0.05);
  EXPECT_LT(worst_angle_deg, 1.5);
  EXPECT_GE(accepted, kFrames - 3);
  EXPECT_EQ(tracker.restarts(), 0u);
}

}  // namespace
}  // namespace dynamap::mapping
