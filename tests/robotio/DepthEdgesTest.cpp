#include "dynamap/robotio/DepthEdges.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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
  const DepthRays rays = DepthToRays(frame, mount, Eigen::Isometry3d::Identity(), 1, {0.05});
  ASSERT_EQ(rays.alongside_range_m.size(), rays.ends.size());
  const std::size_t beside = 60 * 160 + 84;
  const float length_per_depth = (rays.ends[beside] - rays.origin).norm() / 3.0f;
  EXPECT_NEAR(rays.alongside_range_m[beside], 1.0f * length_per_depth, 1e-5f);
  EXPECT_NEAR(rays.surface_range_m[beside], 3.0f * length_per_depth, 1e-5f);
}

TEST(NearestDepthAlongside, ASurfaceAssumedBesideTheSideEdgesReachesTheRaysAlongThem) {
  DepthFrame frame = PostBeforeAWall();
  for (std::uint16_t& d : frame.depth_mm) d = 3000;
  // 5 cm at 1.5 m is 4.4 px (f = 131.25): the windows of radius 1, 2 and 4 reach it.
  const std::vector<float> nearest = NearestDepthAlongside(frame, 0.05, 500, 1.5);
  EXPECT_FLOAT_EQ(At(nearest, 0, 60), 1.5f);
  EXPECT_FLOAT_EQ(At(nearest, 3, 60), 1.5f);
  EXPECT_FLOAT_EQ(At(nearest, 4, 60), 3.0f);
  EXPECT_FLOAT_EQ(At(nearest, 159, 60), 1.5f);
  EXPECT_FLOAT_EQ(At(nearest, 80, 0), 3.0f);  // Top and bottom edges: nothing assumed.
  EXPECT_FLOAT_EQ(At(nearest, 80, 119), 3.0f);
  EXPECT_FLOAT_EQ(At(NearestDepthAlongside(frame, 0.05, 500), 0, 60), 3.0f);
}

// A wall at 3 m; columns 40-59 a surface at 1.5 m seen at grazing incidence, columns
// 60-79 the gap the camera left where that surface grew too grazing.
DepthFrame GrazingSurfaceAndItsGap(std::vector<float>* incidence) {
  DepthFrame frame = PostBeforeAWall();
  incidence->assign(frame.depth_mm.size(), 0.9f);
  for (int v = 0; v < 120; ++v) {
    for (int u = 40; u < 80; ++u) frame.depth_mm[v * 160 + u] = u < 60 ? 1500 : 0;
    for (int u = 40; u < 60; ++u) (*incidence)[v * 160 + u] = 0.3f;
  }
  return frame;
}

TEST(FillGrazingGaps, TheGapBesideAGrazingSurfaceTakesItsDepthWithinReach) {
  std::vector<float> incidence;
  const DepthFrame frame = GrazingSurfaceAndItsGap(&incidence);
  const DepthFrame filled = FillGrazingGaps(frame, incidence, 10, 500);
  EXPECT_EQ(filled.At(60, 50), 1500);  // Next to the last grazing pixel.
  EXPECT_EQ(filled.At(69, 50), 1500);  // 10 px away.
  EXPECT_EQ(filled.At(70, 50), 0);     // 11 px: out of reach.
  EXPECT_EQ(filled.At(50, 50), 1500);  // Measured pixels stay as they are.
  EXPECT_EQ(filled.At(80, 50), 1000);
  EXPECT_EQ(filled.At(100, 50), 3000);
  EXPECT_EQ(FillGrazingGaps(frame, incidence, 0, 500).depth_mm, frame.depth_mm);
}

TEST(FillGrazingGaps, AGapBesideASurfaceSeenHeadOnStaysAGap) {
  std::vector<float> incidence;
  const DepthFrame frame = GrazingSurfaceAndItsGap(&incidence);
  std::fill(incidence.begin(), incidence.end(), 0.9f);
  const DepthFrame filled = FillGrazingGaps(frame, incidence, 10, 500);
  EXPECT_EQ(filled.depth_mm, frame.depth_mm);
}

TEST(FillGrazingGaps, DepthToRaysStopsTheRaysBesideTheGapAtTheGrazingSurface) {
  // A floor-like plane: its rows grow grazing with depth until, beyond 2.4 m (80 deg), the
  // camera drops them; above that gap (4 rows), a wall at 3 m.
  DepthFrame frame = PostBeforeAWall();
  const double f = frame.intrinsics.fy;
  const double cy = frame.intrinsics.cy;
  for (int v = 0; v < 120; ++v) {
    for (int u = 0; u < 160; ++u) frame.depth_mm[v * 160 + u] = 3000;
  }
  // A plane y = 0.4 m below the optical axis (image y down): depth z = 0.4 f / (v - cy).
  for (int v = 0; v < 120; ++v) {
    const double below = v - cy;
    if (below <= 0.0) continue;
    const double z = 0.4 * f / below;
    if (z > 3.0) continue;
    const bool dropped = z > 2.4;
    for (int u = 0; u < 160; ++u) {
      frame.depth_mm[v * 160 + u] = dropped ? 0 : static_cast<std::uint16_t>(std::lround(z * 1000.0));
    }
  }
  KinectMount mount;
  mount.intrinsics = frame.intrinsics;
  mount.max_range_m = 8.0;
  const int row_above_gap = [&] {
    int v = 119;
    while (v > 0 && frame.depth_mm[v * 160 + 80] != 0) --v;  // Up the plane to the gap.
    while (v > 0 && frame.depth_mm[v * 160 + 80] == 0) --v;  // Up the gap to the wall.
    return v;
  }();
  ASSERT_EQ(frame.depth_mm[row_above_gap * 160 + 80], 3000);
  const auto alongside_at = [&](const EdgeClearance& edges) {
    const DepthRays rays = DepthToRays(frame, mount, Eigen::Isometry3d::Identity(), 1, edges);
    std::size_t i = 0;  // Index of pixel (80, row_above_gap) among the measured pixels.
    for (int v = 0; v < row_above_gap; ++v) {
      for (int u = 0; u < 160; ++u) i += frame.depth_mm[v * 160 + u] >= 500 ? 1 : 0;
    }
    return rays.alongside_range_m[i + 80] / (rays.ends[i + 80] - rays.origin).norm() * 3.0f;
  };
  EdgeClearance edges;
  edges.lateral_m = 0.05;
  EXPECT_NEAR(alongside_at(edges), 3.0f, 1e-3f);  // Nothing measured nearer beside it.
  edges.grazing_gap_px = 8;
  EXPECT_LT(alongside_at(edges), 2.4f);  // The plane's measured rows within 8 px.
  // Grazing pixels below the height (in the target frame, here the optical one, whose z is
  // the depth) fill nothing.
  edges.gap_min_height_m = 5.0;
  EXPECT_NEAR(alongside_at(edges), 3.0f, 1e-3f);
}

}  // namespace
}  // namespace dynamap::robotio
