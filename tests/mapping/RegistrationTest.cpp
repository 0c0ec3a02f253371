#include "dynamap/mapping/Registration.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace dynamap::mapping {
namespace {

using robotio::PointList;

// The x y z columns of an ASCII PCD file (PCL's test clouds).
PointList ReadAsciiPcdXyz(const std::string& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in.good()) << file;
  PointList points;
  std::string line;
  bool data = false;
  while (std::getline(in, line)) {
    if (!data) {
      data = line.rfind("DATA ascii", 0) == 0;
      continue;
    }
    std::istringstream fields(line);
    float x = 0, y = 0, z = 0;
    if (fields >> x >> y >> z) points.emplace_back(x, y, z);
  }
  return points;
}

std::string PclData(const std::string& name) {
  return std::string(DYNAMAP_SHARED_DATA_DIR) + "/pcl/" + name;
}

// A room corner with a floor, two walls and a box: enough structure to fix x, y and yaw.
PointList Room(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::normal_distribution<float> noise(0.0f, 0.003f);
  PointList points;
  for (int i = 0; i < 1500; ++i) {
    points.emplace_back(4.0f * u(rng), -2.0f + 4.0f * u(rng), noise(rng));         // floor
    points.emplace_back(4.0f + noise(rng), -2.0f + 4.0f * u(rng), 2.0f * u(rng));  // front
    points.emplace_back(4.0f * u(rng), 2.0f + noise(rng), 2.0f * u(rng));          // left
  }
  for (int i = 0; i < 500; ++i)
    points.emplace_back(2.0f + 0.5f * u(rng), -1.0f + noise(rng), 0.8f * u(rng));  // box side
  return points;
}

PointList Transformed(const PointList& points, const Eigen::Isometry3d& T) {
  PointList out;
  out.reserve(points.size());
  for (const auto& p : points) out.push_back((T.cast<float>() * p));
  return out;
}

TEST(Registration, BunnyPointToPointReproducesPclExpectation) {
  const PointList source = ReadAsciiPcdXyz(PclData("bun0.pcd"));
  const PointList target = ReadAsciiPcdXyz(PclData("bun4.pcd"));
  ASSERT_EQ(source.size(), 397u);
  ASSERT_EQ(target.size(), 361u);
  // PCL's test settings (test/registration/test_registration.cpp).
  RegistrationConfig config;
  config.metric = IcpMetric::kPointToPoint;
  config.planar = false;
  config.trim_ratio = 1.0;
  config.max_iterations = 50;
  config.transformation_epsilon = 1e-8;
  config.euclidean_fitness_epsilon = 0.0;
  config.max_correspondence_distance_m = 0.05;
  const auto result = RegisterScans(source, target, Eigen::Isometry3d::Identity(), config);
  Eigen::Matrix<double, 3, 4> expected;
  expected << 0.8806, 0.0365, -0.4724, 0.03453,  //
      -0.02354, 0.9992, 0.03326, -0.001519,      //
      0.4732, -0.01817, 0.8808, 0.04116;
  const Eigen::Matrix<double, 3, 4> actual = result.T_target_source.matrix().topRows<3>();
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 4; ++c) {
      const double tolerance = (r == 0 && c == 1) ? 1e-2 : 1e-3;
      EXPECT_NEAR(actual(r, c), expected(r, c), tolerance) << "entry (" << r << "," << c << ")";
    }
  }
  EXPECT_GT(result.iterations, 1);
  EXPECT_GT(result.inlier_ratio, 0.5);
}

class PlanarRegistration : public ::testing::TestWithParam<IcpMetric> {};

TEST_P(PlanarRegistration, RecoversPlanarOffsetFromRoughGuess) {
  const PointList target = Room(1);
  const Eigen::Isometry3d truth_T_target_source(Eigen::Translation3d(0.12, -0.08, 0.0) *
                                                Eigen::AngleAxisd(0.06, Eigen::Vector3d::UnitZ()));
  // A fresh sample of the same room, seen from the offset pose.
  const PointList source = Transformed(Room(2), truth_T_target_source.inverse());
  RegistrationConfig config;
  config.metric = GetParam();
  const auto result = RegisterScans(source, target, Eigen::Isometry3d::Identity(), config);
  EXPECT_TRUE(result.converged);
  const Eigen::Isometry3d error = truth_T_target_source.inverse() * result.T_target_source;
  EXPECT_LT(error.translation().norm(), 0.01);
  EXPECT_LT(Eigen::AngleAxisd(error.linear()).angle(), 0.005);
  EXPECT_GT(result.inlier_ratio, 0.9);
  // The two samples are independent, ~10 cm apart on the floor: nearest neighbours lie
  // a few centimetres apart even at the true pose.
  EXPECT_LT(result.fitness_rmse_m, 0.06);
  // Planar: no height or tilt is invented.
  EXPECT_NEAR(result.T_target_source.translation().z(), 0.0, 1e-6);
  EXPECT_NEAR(result.T_target_source.linear()(2, 2), 1.0, 1e-6);
}

TEST_P(PlanarRegistration, TrimmingIgnoresAForeignObject) {
  const PointList target = Room(3);
  const Eigen::Isometry3d truth(Eigen::Translation3d(0.05, 0.05, 0.0) *
                                Eigen::AngleAxisd(-0.03, Eigen::Vector3d::UnitZ()));
  PointList source = Transformed(Room(4), truth.inverse());
  // A screen carried through the scene: a dense plane not in the reference.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  for (int i = 0; i < 800; ++i) source.emplace_back(1.5f, -0.5f + 1.5f * u(rng), 1.0f * u(rng));
  RegistrationConfig config;
  config.metric = GetParam();
  config.trim_ratio = 0.8;
  const auto result = RegisterScans(source, target, Eigen::Isometry3d::Identity(), config);
  const Eigen::Isometry3d error = truth.inverse() * result.T_target_source;
  EXPECT_LT(error.translation().norm(), 0.01);
  EXPECT_LT(result.inlier_ratio, 0.95);  // The screen has no partner in the reference.
}

INSTANTIATE_TEST_SUITE_P(Metrics, PlanarRegistration,
                         ::testing::Values(IcpMetric::kPointToPoint, IcpMetric::kPointToPlane));

TEST(Registration, TooFewPointsIsNotConverged) {
  const PointList few = {Eigen::Vector3f(1, 0, 0), Eigen::Vector3f(0, 1, 0)};
  const auto result = RegisterScans(few, Room(1), Eigen::Isometry3d::Identity(), {});
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.inlier_ratio, 0.0);
}

}  // namespace
}  // namespace dynamap::mapping
