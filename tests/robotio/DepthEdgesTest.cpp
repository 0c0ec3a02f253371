#include "dynamap/robotio/DepthEdges.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::robotio {
namespace {

// 160 x 120 (f = 131.25 px): a wall at 3 m and, in front of it, a post 1 m away in columns
// 80 and 81.
DepthFrame PostBeforeAWall() {
  DepthFrame frame;
  frame.intrinsics = Intrinsics{}.Scaled(160, 120);
  frame.width = 160;
  frame.height = 120;
  frame.depth_mm.assign(160 * 120, 3000);
  for (int v = 0; v < 120; ++v) {
    frame.depth_mm[v * 160 + 80] = 1000;
    frame.depth_mm[v * 160 + 81] = 1000;
  }
  return frame;
}

float At(const std::vector<float>& image, int u, int v) { return image[v * 160 + u]; }

TEST(NearestDepthAlongside, RaysBesideThePostPassItRaysFartherOffDoNot) {
  const std::vector<float> nearest = NearestDepthAlongside(PostBeforeAWall(), 0.05, 500);
  EXPECT_FLOAT_EQ(At(nearest, 80, 60), 1.0f);  // The post itself.
  EXPECT_FLOAT_EQ(At(nearest, 84, 60), 1.0f);  // 3 px, 2.3 cm beside it at 1 m.
  EXPECT_FLOAT_EQ(At(nearest, 77, 60), 1.0f);
  EXPECT_FLOAT_EQ(At(nearest, 93, 60), 3.0f);  // 12 px, 9 cm: the wall it measured.
  EXPECT_FLOAT_EQ(At(nearest, 10, 10), 3.0f);
}

TEST(NearestDepthAlongside, NeverCountsAPixelFartherThanTheDistance) {
  // Every pixel's answer is a depth measured within lateral_m of its ray, for several
  // distances (the search is by windows, so it may find less, never more).
  const DepthFrame frame = PostBeforeAWall();
  for (const double lateral : {0.01, 0.03, 0.05, 0.2}) {
    const std::vector<float> nearest = NearestDepthAlongside(frame, lateral, 500);
    for (int u = 0; u < 160; ++u) {
      const int offset = u < 80 ? 80 - u : (u > 81 ? u - 81 : 0);
      const float post_reach = static_cast<float>(offset * 1.0 / frame.intrinsics.fx);
      if (post_reach > lateral) {
        EXPECT_FLOAT_EQ(At(nearest, u, 60), 3.0f) << u << " " << lateral;
      }
    }
  }
}

TEST(NearestDepthAlongside, MissingAndTooNearPixelsAreNoMeasurement) {
  DepthFrame frame = PostBeforeAWall();
  for (std::uint16_t& d : frame.depth_mm) d = 0;
  frame.depth_mm[60 * 160 + 20] = 300;  // Below the 0.5 m minimum.
  const std::vector<float> nearest = NearestDepthAlongside(frame, 0.05, 500);
  EXPECT_TRUE(std::isinf(At(nearest, 20, 60)));
  EXPECT_TRUE(std::isinf(At(nearest, 100, 100)));
}

TEST(NearestDepthAlongside, DepthToRaysCarriesItAsARangeAlongEachRay) {
  const DepthFrame frame = PostBeforeAWall();
  KinectMount mount;
  mount.intrinsics = frame.intrinsics;
  EXPECT_TRUE(DepthToRays(frame, mount, Eigen::Isometry3d::Identity()).alongside_range_m.empty());
  const DepthRays rays = DepthToRays(frame, mount, Eigen::Isometry3d::Identity(), 1, 0.05);
  ASSERT_EQ(rays.alongside_range_m.size(), rays.ends.size());
  const std::size_t beside = 60 * 160 + 84;
  const float length_per_depth = (rays.ends[beside] - rays.origin).norm() / 3.0f;
  EXPECT_NEAR(rays.alongside_range_m[beside], 1.0f * length_per_depth, 1e-5f);
  EXPECT_NEAR(rays.surface_range_m[beside], 3.0f * length_per_depth, 1e-5f);
}

}  // namespace
}  // namespace dynamap::robotio
