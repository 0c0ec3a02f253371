#include "dynamap/robotio/DepthProjection.hpp"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>

#include "TestPaths.hpp"
#include "dynamap/robotio/DepthImageIo.hpp"
#include "dynamap/robotio/RecordingReader.hpp"

namespace dynamap::robotio {
namespace {

constexpr const char* kKinectFrame = "kinect/frame_20121214T142255.814212";

DepthFrame LoadKinectFrame() {
  auto image = ReadDepthImage(test::SharedData(std::string(kKinectFrame) + "_depth.tiff"));
  EXPECT_TRUE(image.ok()) << image.error().message;
  DepthFrame frame;
  frame.width = image->width;
  frame.height = image->height;
  frame.intrinsics = Intrinsics{640, 480, 525.0, 525.0, 320.0, 240.0};  // The .xml beside it.
  frame.depth_mm = image->values;
  return frame;
}

TEST(DepthProjection, RealKinectFrameMatchesPclOrganizedCloud) {
  const DepthFrame frame = LoadKinectFrame();
  ASSERT_EQ(frame.width, 640);
  ASSERT_EQ(frame.height, 480);
  pcl::PointCloud<pcl::PointXYZRGBA> reference;
  ASSERT_EQ(pcl::io::loadPCDFile(test::SharedData(std::string(kKinectFrame) + ".pcd"), reference),
            0);
  ASSERT_EQ(reference.size(), 640u * 480u);

  const PointList points = DepthToOrganizedPoints(frame);
  ASSERT_EQ(points.size(), reference.size());
  int valid = 0;
  double max_error = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& r = reference[i];
    if (frame.depth_mm[i] == 0) {
      EXPECT_TRUE(std::isnan(points[i].x()) && std::isnan(r.x)) << "pixel " << i;
      continue;
    }
    ++valid;
    max_error = std::max({max_error, std::abs(double(points[i].x()) - r.x),
                          std::abs(double(points[i].y()) - r.y),
                          std::abs(double(points[i].z()) - r.z)});
  }
  EXPECT_EQ(valid, 271575);
  EXPECT_LE(max_error, 1e-6);
}

TEST(DepthProjection, RealKinectFrameSpansTheDocumentedDepths) {
  const DepthFrame frame = LoadKinectFrame();
  const PointList points = DepthToPoints(frame, 0.0, 10.0);
  ASSERT_EQ(points.size(), 271575u);
  const auto [lo, hi] = std::minmax_element(
      points.begin(), points.end(), [](const auto& a, const auto& b) { return a.z() < b.z(); });
  EXPECT_NEAR(lo->z(), 0.671, 1e-3);
  EXPECT_NEAR(hi->z(), 1.713, 1e-3);
}

TEST(DepthProjection, TumDepthPngHasTheDocumentedValidPixelsAndTruncatedMaximum) {
  auto frame = ReadTumDepthPng(test::SharedData("tum/TUM_depth.png"));
  ASSERT_TRUE(frame.ok()) << frame.error().message;
  EXPECT_EQ(frame->width, 640);
  EXPECT_EQ(frame->height, 480);
  const auto valid = std::count_if(frame->depth_mm.begin(), frame->depth_mm.end(),
                                   [](std::uint16_t d) { return d != 0; });
  EXPECT_EQ(valid, 248250);
  const PointList kept = DepthToPoints(*frame, 0.0, 4.0);
  float max_z = 0.0f;
  for (const auto& p : kept) max_z = std::max(max_z, p.z());
  EXPECT_NEAR(max_z, 3.994, 1e-3);
}

TEST(DepthProjection, BasePointsUseTheMountPose) {
  DepthFrame frame;
  frame.width = 3;
  frame.height = 3;
  frame.intrinsics = Intrinsics{3, 3, 3.0, 3.0, 1.0, 1.0};
  frame.depth_mm.assign(9, 0);
  frame.depth_mm[4] = 2000;  // Centre pixel, 2 m along the optical axis.
  KinectMount mount;
  mount.T_base_kinect = MountPose({0.1, 0.0, 0.6}, Eigen::Vector3d(M_PI, 0.0, M_PI / 2));
  const PointList points = DepthToBasePoints(frame, mount);
  ASSERT_EQ(points.size(), 1u);
  // Yawed 90°: looks along base +y.
  EXPECT_NEAR(points[0].x(), 0.1, 1e-6);
  EXPECT_NEAR(points[0].y(), 2.0, 1e-6);
  EXPECT_NEAR(points[0].z(), 0.6, 1e-6);
}

TEST(DepthProjection, RaysBeyondMaxRangeAreCutAtTheMaxRangeDepthAndMarkedAsMisses) {
  DepthFrame frame;
  frame.width = 3;
  frame.height = 1;
  // Pixels 0 and 2 look 45 degrees beside the axis (|u - cx| = fx), pixel 1 along it.
  frame.intrinsics = Intrinsics{3, 1, 1.0, 1.0, 1.0, 0.0};
  frame.depth_mm = {3900, 1500, 6000};
  KinectMount mount;
  mount.max_range_m = 4.0;
  const DepthRays rays = DepthToRays(frame, mount, Eigen::Isometry3d::Identity());
  ASSERT_EQ(rays.ends.size(), 3u);
  EXPECT_TRUE(rays.hit[0]);
  EXPECT_TRUE(rays.hit[1]);
  EXPECT_FALSE(rays.hit[2]);
  // Max range is a depth: a hit 3.9 m deep lies 5.5 m along its ray, and a longer ray
  // beside the axis is cut 4 m deep, past that hit, not 4 m along the ray.
  EXPECT_NEAR((rays.ends[0] - rays.origin).norm(), 3.9 * std::sqrt(2.0), 1e-4);
  EXPECT_NEAR(rays.ends[2].z(), 4.0, 1e-5);
  EXPECT_NEAR((rays.ends[2] - rays.origin).norm(), 4.0 * std::sqrt(2.0), 1e-4);
}

// A 5x5 image of the plane z = 2 + slope * y (optical frame): tilted by atan(slope)
// about x, so the centre ray meets it at cos = 1 / sqrt(1 + slope^2).
DepthFrame TiltedPlane(double slope) {
  DepthFrame frame;
  frame.width = 5;
  frame.height = 5;
  frame.intrinsics = Intrinsics{5, 5, 100.0, 100.0, 2.0, 2.0};
  for (int v = 0; v < 5; ++v) {
    for (int u = 0; u < 5; ++u) {
      const double y_over_z = (v - 2.0) / 100.0;
      const double z = 2.0 / (1.0 - slope * y_over_z);
      frame.depth_mm.push_back(static_cast<std::uint16_t>(std::lround(z * 1000.0)));
    }
  }
  return frame;
}

TEST(DepthProjection, RaysCarryTheIncidenceOfTheSurfaceTheyHit) {
  KinectMount mount;
  const std::size_t centre = 2 * 5 + 2;
  const DepthRays head_on = DepthToRays(TiltedPlane(0.0), mount, Eigen::Isometry3d::Identity());
  ASSERT_EQ(head_on.incidence_cos.size(), head_on.ends.size());
  EXPECT_NEAR(head_on.incidence_cos[centre], 1.0, 1e-3);
  const DepthRays grazing = DepthToRays(TiltedPlane(4.0), mount, Eigen::Isometry3d::Identity());
  EXPECT_NEAR(grazing.incidence_cos[centre], 1.0 / std::sqrt(17.0), 0.02);
}

TEST(DepthProjection, PixelsWithoutNeighboursCountAsGrazing) {
  DepthFrame frame;
  frame.width = 3;
  frame.height = 1;
  frame.intrinsics = Intrinsics{3, 1, 100.0, 100.0, 1.0, 0.0};
  frame.depth_mm = {0, 1500, 0};
  const DepthRays rays = DepthToRays(frame, KinectMount{}, Eigen::Isometry3d::Identity());
  ASSERT_EQ(rays.incidence_cos.size(), 1u);
  EXPECT_EQ(rays.incidence_cos[0], 0.0f);
}

TEST(DepthImageIo, NonDepthImageIsAnErrorNamingTheFile) {
  auto image = ReadDepthImage(test::SharedData("movingai/arena.map"));
  ASSERT_FALSE(image.ok());
  EXPECT_NE(image.error().message.find("arena.map"), std::string::npos);
}

}  // namespace
}  // namespace dynamap::robotio
