#include "dynamap/calibration/FloorPlane.hpp"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <cmath>
#include <filesystem>
#include <random>

namespace dynamap::calibration {
namespace {

constexpr double kDeg = M_PI / 180.0;

std::string SharedData(const std::string& relative) {
  return (std::filesystem::path(DYNAMAP_SHARED_DATA_DIR) / relative).string();
}

// PCL's own test (test_sample_consensus_plane_models.cpp): RANSAC with a 3 cm threshold
// finds > 2000 inliers and a/d = -0.8964, b/d = -0.5868, c/d = -1.208 (each within 0.1).
TEST(FloorPlane, SacPlaneTestMeetsPclExpectation) {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  ASSERT_EQ(pcl::io::loadPCDFile(SharedData("pcl/sac_plane_test.pcd"), cloud), 0);
  robotio::PointList points;
  for (const auto& p : cloud) points.emplace_back(p.x, p.y, p.z);
  PlaneFitConfig config;
  config.distance_threshold_m = 0.03;
  const PlaneFit fit = FitPlane(points, config);
  ASSERT_TRUE(fit.ok);
  EXPECT_GT(fit.inliers, 2000u);
  const double d = fit.distance_m;
  EXPECT_NEAR(fit.normal.x() / d, -0.8964, 0.1);
  EXPECT_NEAR(fit.normal.y() / d, -0.5868, 0.1);
  EXPECT_NEAR(fit.normal.z() / d, -1.208, 0.1);
  EXPECT_LT(fit.rms_m, 0.03);
}

// A Kinect mounted upside down, tilted down 12°, 0.62 m up: a noisy floor plus a wall that
// (0.125 m to 1.475 m high, like furniture) holds more points than the floor. The fit must find the floor, not the wall.
TEST(FloorPlane, FloorGivesRollPitchHeightEvenBesideALargerWall) {
  const Eigen::Isometry3d T_base_kinect =
      robotio::MountPose({0.1, 0.0, 0.62}, Eigen::Vector3d(178.0, 12.0, 30.0) * kDeg);
  const Eigen::Isometry3d T_kinect_base = T_base_kinect.inverse();
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  std::normal_distribution<double> noise(0.0, 0.005);
  robotio::PointList points;
  for (int i = 0; i < 3000; ++i) {
    const Eigen::Vector3d floor_point(1.0 + 0.5 * (u(rng) + 1.5), u(rng), noise(rng));
    points.push_back((T_kinect_base * floor_point).cast<float>());
  }
  for (int i = 0; i < 5000; ++i) {
    const Eigen::Vector3d wall_point(3.0 + noise(rng), u(rng), 0.8 + 0.45 * u(rng));
    points.push_back((T_kinect_base * wall_point).cast<float>());
  }
  // The guess is 8° off in roll and pitch: the fit must still accept the floor.
  const Eigen::Isometry3d guess =
      robotio::MountPose({0, 0, 0.5}, Eigen::Vector3d(170.0, 4.0, 0.0) * kDeg);
  const PlaneFit fit = FitPlane(points, PlaneFitConfig{}, FloorNormalInKinect(guess));
  ASSERT_TRUE(fit.ok);
  const FloorPose pose = FloorPoseFromPlane(fit);
  const Eigen::Vector3d rpy = robotio::MountRollPitchYaw(T_base_kinect);
  EXPECT_NEAR(std::remainder(pose.roll_rad - rpy.x(), 2 * M_PI) / kDeg, 0.0, 0.1);
  EXPECT_NEAR((pose.pitch_rad - rpy.y()) / kDeg, 0.0, 0.1);
  EXPECT_NEAR(pose.height_m, 0.62, 0.002);
  EXPECT_NEAR(pose.inlier_share, 3000.0 / 8000.0, 0.02);
}

// Walls standing on the floor put their feet (0 to 3 cm up) inside RANSAC's 3 cm band, at
// the far end of the view where they tilt the plane. The narrowed refit must leave them out.
TEST(FloorPlane, WallFeetInTheInlierBandDoNotTiltTheFloor) {
  const Eigen::Isometry3d T_base_kinect =
      robotio::MountPose({0.2, 0.0, 0.55}, Eigen::Vector3d(0.0, 15.0, 0.0) * kDeg);
  const Eigen::Isometry3d T_kinect_base = T_base_kinect.inverse();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> along(0.6, 3.0);
  std::uniform_real_distribution<double> across(-1.5, 1.5);
  std::uniform_real_distribution<double> height(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.002);
  robotio::PointList points;
  for (int i = 0; i < 4000; ++i) {
    const Eigen::Vector3d p(along(rng), across(rng), noise(rng));
    points.push_back((T_kinect_base * p).cast<float>());
  }
  for (int i = 0; i < 3000; ++i) {  // Wall at x = 3 m, from the floor up to 1 m.
    const Eigen::Vector3d p(3.0 + noise(rng), across(rng), height(rng));
    points.push_back((T_kinect_base * p).cast<float>());
  }
  const PlaneFit fit = FitPlane(points, PlaneFitConfig{}, FloorNormalInKinect(T_base_kinect));
  ASSERT_TRUE(fit.ok);
  const FloorPose pose = FloorPoseFromPlane(fit);
  EXPECT_NEAR(pose.pitch_rad / kDeg, 15.0, 0.02);
  EXPECT_NEAR(std::remainder(pose.roll_rad, 2 * M_PI) / kDeg, 0.0, 0.02);
  EXPECT_NEAR(pose.height_m, 0.55, 0.0005);
  EXPECT_LT(fit.rms_m, 0.003);

  // The single wide band alone is what tilted it.
  PlaneFitConfig wide;
  wide.narrowing_rounds = 0;
  const FloorPose tilted =
      FloorPoseFromPlane(FitPlane(points, wide, FloorNormalInKinect(T_base_kinect)));
  EXPECT_GT(std::abs(tilted.pitch_rad / kDeg - 15.0) + std::abs(tilted.height_m - 0.55) * 100.0,
            0.05);
}

TEST(FloorPlane, CombinedFitsAverageAndCount) {
  PlaneFit a;
  a.ok = true;
  a.normal = Eigen::Vector3d(0, -1, 0);
  a.distance_m = 0.6;
  a.inlier_share = 0.5;
  PlaneFit b = a;
  b.distance_m = 0.62;
  PlaneFit failed;
  const FloorPose pose = CombineFloorFits({a, b, failed});
  EXPECT_EQ(pose.frames, 2);
  EXPECT_NEAR(pose.height_m, 0.61, 1e-12);
  EXPECT_EQ(CombineFloorFits({failed}).frames, 0);
}

}  // namespace
}  // namespace dynamap::calibration
