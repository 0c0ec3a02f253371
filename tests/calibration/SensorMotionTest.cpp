#include "dynamap/calibration/SensorMotion.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <random>

namespace dynamap::calibration {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Floor, two walls and a box as seen from a sensor at the origin (optical frame: z ahead).
robotio::PointList Room(bool floor_only, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 0.002);
  robotio::PointList points;
  for (int i = 0; i < 6000; ++i) {  // Floor 0.6 m below (optical y down).
    points.emplace_back(-2.0 + 4.0 * u(rng), 0.6 + noise(rng), 0.8 + 3.0 * u(rng));
  }
  if (floor_only) return points;
  for (int i = 0; i < 4000; ++i) {  // Wall ahead and wall to the left.
    points.emplace_back(-2.0 + 4.0 * u(rng), 0.6 - 2.0 * u(rng), 3.8 + noise(rng));
    points.emplace_back(-2.0 + noise(rng), 0.6 - 2.0 * u(rng), 0.8 + 3.0 * u(rng));
  }
  for (int i = 0; i < 2000; ++i) {  // Box face towards the sensor and its top.
    points.emplace_back(0.5 + 0.6 * u(rng), 0.6 - 0.5 * u(rng), 2.0 + noise(rng));
    points.emplace_back(0.5 + 0.6 * u(rng), 0.1 + noise(rng), 2.0 + 0.4 * u(rng));
  }
  return points;
}

robotio::PointList Transformed(const robotio::PointList& points, const Eigen::Isometry3d& T) {
  robotio::PointList out;
  for (const auto& p : points) out.push_back((T * p.cast<double>()).cast<float>());
  return out;
}

TEST(SensorMotion, IcpRecoversMotionInAStructuredRoom) {
  // The sensor moved 10 cm forward, 3 cm right and turned 4° (about optical -y, i.e. left).
  Eigen::Isometry3d T_from_to = Eigen::Isometry3d::Identity();
  T_from_to.linear() = Eigen::AngleAxisd(-4.0 * kDeg, Eigen::Vector3d::UnitY()).toRotationMatrix();
  T_from_to.translation() = Eigen::Vector3d(0.03, 0.0, 0.10);
  const robotio::PointList from = Room(false, 1);
  const robotio::PointList to = Transformed(Room(false, 2), T_from_to.inverse());
  const IcpConfig config;
  const SensorMotionResult r = EstimateSensorMotion(
      PrepareCloud(from, config), PrepareCloud(to, config), Eigen::Isometry3d::Identity(), config);
  ASSERT_TRUE(r.accepted) << "rms " << r.rms_m << " structure " << r.structure;
  EXPECT_LT((r.T_from_to.translation() - T_from_to.translation()).norm(), 0.005);
  EXPECT_LT(Eigen::AngleAxisd(r.T_from_to.linear().transpose() * T_from_to.linear()).angle(),
            0.2 * kDeg);
  EXPECT_GT(r.structure, config.min_structure);
}

TEST(SensorMotion, BareFloorLacksStructureAndIsRejected) {
  const robotio::PointList floor = Room(true, 3);
  const IcpConfig config;
  const PreparedCloud cloud = PrepareCloud(floor, config);
  const SensorMotionResult r =
      EstimateSensorMotion(cloud, PrepareCloud(Room(true, 4), config),
                           Eigen::Isometry3d::Identity(), config);
  EXPECT_FALSE(r.accepted);
  EXPECT_LT(r.structure, config.min_structure);
  // Its information says which directions the floor cannot pin: sliding along it (optical
  // x and z) and turning about its normal (optical y); moving off it is pinned.
  using Matrix6 = Eigen::Matrix<double, 6, 6>;
  const double largest = Eigen::SelfAdjointEigenSolver<Matrix6>(r.information).eigenvalues()(5);
  EXPECT_NEAR(largest, 1.0, 1e-9);
  EXPECT_LT(r.information(3, 3), 1e-3);
  EXPECT_LT(r.information(5, 5), 1e-3);
  EXPECT_LT(r.information(1, 1), 1e-3);
  EXPECT_GT(r.information(4, 4), 0.3);
  EXPECT_GT(r.lever_m, 0.8);
}

}  // namespace
}  // namespace dynamap::calibration
