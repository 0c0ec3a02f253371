#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "SimTestWorlds.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/sim/DepthRenderer.hpp"

namespace dynamap::robotio::sim {
namespace {

constexpr double kDeg = M_PI / 180.0;

KinectModelConfig Exact() {
  KinectModelConfig model;
  model.enabled = false;
  return model;
}

// Depth (optical z) of pixel (u, v) for a camera at T_world_kinect looking at the planes
// x = wall_x and z = 0 (floor), whichever is hit first.
double ExpectedDepth(const Eigen::Isometry3d& T, const Intrinsics& k, int u, int v, double wall_x) {
  const Eigen::Vector3d d = T.linear() * Eigen::Vector3d((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
  const Eigen::Vector3d o = T.translation();
  double t = std::numeric_limits<double>::infinity();
  if (d.x() > 1e-9) t = std::min(t, (wall_x - o.x()) / d.x());
  if (d.z() < -1e-9) t = std::min(t, -o.z() / d.z());
  return t;
}

Intrinsics SmallIntrinsics() { return Intrinsics{}.Scaled(160, 120); }

void ExpectMatchesGeometry(const Eigen::Isometry3d& T_world_kinect, double wall_x) {
  const World world = testing::MustParse(testing::WallWorldYaml(wall_x));
  DepthRenderer renderer(world, 2);
  const Intrinsics k = SmallIntrinsics();
  KinectModelConfig model = Exact();
  const RenderedImage image = renderer.Render(T_world_kinect, k, 0.5, model, 1);
  ASSERT_EQ(image.depth.width, 160);
  ASSERT_EQ(image.depth.height, 120);
  for (const auto& [u, v] : {std::pair{0, 0}, {159, 0}, {0, 119}, {159, 119}, {80, 60}, {40, 90}}) {
    const double expected = ExpectedDepth(T_world_kinect, k, u, v, wall_x);
    ASSERT_LT(expected, model.far_limit_m) << u << "," << v;
    EXPECT_NEAR(image.depth.At(u, v) * 1e-3, expected, 1.5e-3) << "pixel " << u << "," << v;
  }
}

TEST(DepthRenderer, WallAlongTheOpticalAxisAtKnownDistance) {
  const World world = testing::MustParse(testing::WallWorldYaml(2.5));
  DepthRenderer renderer(world, 2);
  // Level Kinect looking along base x at 1 m height.
  const Eigen::Isometry3d T = MountPose({0, 0, 1.0}, {0, 0, 0});
  const Intrinsics k = SmallIntrinsics();
  const RenderedImage image = renderer.Render(T, k, 0.5, Exact(), 1);
  EXPECT_EQ(image.depth.At(80, 60), 2500);
  EXPECT_EQ(image.depth.At(0, 0), 2500);  // A wall facing the camera has constant depth.
}

TEST(DepthRenderer, ImageCornersOfAYawedPitchedCamera) {
  ExpectMatchesGeometry(MountPose({0.1, 0.2, 0.6}, {0.0, 12 * kDeg, 25 * kDeg}), 3.0);
}

TEST(DepthRenderer, ImageCornersOfAnUpsideDownMount) {
  const Eigen::Isometry3d T = MountPose({0.12, 0.08, 0.60}, {180 * kDeg, 8 * kDeg, 29 * kDeg});
  ExpectMatchesGeometry(T, 3.0);
  // Upside down, the top image row looks down at the floor and the bottom row up the wall.
  const World world = testing::MustParse(testing::WallWorldYaml(3.0));
  DepthRenderer renderer(world, 2);
  const RenderedImage image = renderer.Render(T, SmallIntrinsics(), 0.5, Exact(), 1);
  const auto wall_label = static_cast<std::uint16_t>(world.FindObject("wall") + 1);
  EXPECT_EQ(image.labels.labels[0 * 160 + 80], 1);  // floor = object 0
  EXPECT_EQ(image.labels.labels[119 * 160 + 80], wall_label);
}

}  // namespace
}  // namespace dynamap::robotio::sim
