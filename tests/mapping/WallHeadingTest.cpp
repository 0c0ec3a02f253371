// The heading from walls at right angles: line pieces, the axis direction in one scan,
// the building's axes learnt and then measured against.
#include "dynamap/mapping/WallHeading.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace dynamap::mapping {
namespace {

constexpr double kDegree = M_PI / 180.0;
// One scan's walls carry 1 cm of noise across them: each line piece's direction is off by
// about a degree, the mean of a scan's pieces by under a fifth of one.
constexpr double kScanTolerance = 0.3 * kDegree;

// Points on a wall from `a` to `b` (x/y), 0.3-1.8 m high, with `noise_m` across it.
void AddWall(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double noise_m,
             std::mt19937* rng, robotio::PointList* points) {
  std::normal_distribution<double> noise(0.0, noise_m);
  const Eigen::Vector2d along = b - a;
  const Eigen::Vector2d across = Eigen::Vector2d(-along.y(), along.x()).normalized();
  const int steps = static_cast<int>(along.norm() / 0.03);
  for (int i = 0; i <= steps; ++i) {
    for (double z = 0.3; z <= 1.8; z += 0.1) {
      const Eigen::Vector2d p = a + along * (static_cast<double>(i) / steps) + across * noise(*rng);
      points->emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                           static_cast<float>(z));
    }
  }
}

// A room's corner seen from inside: walls along the building's axes, the robot turned by
// `heading` (so in its frame the walls run at -heading), a floor, a round pillar and a
// board leaning at 30°.
robotio::PointList RoomCorner(double heading, std::mt19937* rng) {
  const Eigen::Rotation2Dd to_base(-heading);
  robotio::PointList world;
  AddWall({-1.0, 3.0}, {4.0, 3.0}, 0.01, rng, &world);
  AddWall({4.0, 3.0}, {4.0, -2.0}, 0.01, rng, &world);
  const Eigen::Vector2d board = Eigen::Rotation2Dd(30.0 * kDegree) * Eigen::Vector2d(1.0, 0.0);
  AddWall({1.0, 0.5}, Eigen::Vector2d(1.0, 0.5) + 1.2 * board, 0.01, rng, &world);
  for (double a = 0.0; a < 2.0 * M_PI; a += 0.1) {
    for (double z = 0.3; z <= 1.8; z += 0.1) {
      world.emplace_back(static_cast<float>(2.5 + 0.2 * std::cos(a)),
                         static_cast<float>(1.5 + 0.2 * std::sin(a)), static_cast<float>(z));
    }
  }
  for (double x = 0.5; x < 3.5; x += 0.05) {
    for (double y = -1.5; y < 2.5; y += 0.05) {
      world.emplace_back(static_cast<float>(x), static_cast<float>(y), 0.0f);
    }
  }
  robotio::PointList base;
  for (const auto& p : world) {
    const Eigen::Vector2d xy = to_base * Eigen::Vector2d(p.x(), p.y());
    base.emplace_back(static_cast<float>(xy.x()), static_cast<float>(xy.y()), p.z());
  }
  return base;
}

TEST(WallHeading, AnglesWrapToAQuarterTurn) {
  EXPECT_NEAR(WrapQuarter(0.0), 0.0, 1e-12);
  EXPECT_NEAR(WrapQuarter(M_PI / 2.0 + 0.1), 0.1, 1e-12);
  EXPECT_NEAR(WrapQuarter(-M_PI + 0.2), 0.2, 1e-12);
  EXPECT_NEAR(WrapQuarter(M_PI / 4.0 + 0.01), -M_PI / 4.0 + 0.01, 1e-12);
}

// Both walls of a corner give the same direction modulo 90°; the floor, the pillar and the
// board leaning at 30° do not move it.
TEST(WallHeading, TheWallsOfACornerGiveTheirDirection) {
  std::mt19937 rng(3);
  const WallHeadingConfig config;
  for (double heading_deg : {0.0, 17.0, -40.0, 95.5}) {
    const auto pieces = LinePieces(RoomCorner(heading_deg * kDegree, &rng), config);
    ASSERT_FALSE(pieces.empty());
    const auto direction = DominantDirection(pieces, config);
    ASSERT_TRUE(direction.has_value()) << heading_deg;
    EXPECT_NEAR(WrapQuarter(*direction + heading_deg * kDegree), 0.0, kScanTolerance)
        << heading_deg;
  }
}

// Points with no straight structure (a scatter, a round pillar alone) say nothing.
TEST(WallHeading, ScatteredPointsGiveNoDirection) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  robotio::PointList scatter;
  for (int i = 0; i < 4000; ++i) {
    scatter.emplace_back(static_cast<float>(u(rng)), static_cast<float>(u(rng)),
                         static_cast<float>(1.0 + 0.2 * u(rng)));
  }
  const WallHeadingConfig config;
  EXPECT_FALSE(DominantDirection(LinePieces(scatter, config), config).has_value());
}

// The axes are learnt from the first scans; then a scan's walls measure the heading, a
// wrong estimate included, and walls off the axes (a wing built at 30°) measure nothing.
TEST(WallHeading, LearnsTheAxesThenMeasuresTheHeading) {
  std::mt19937 rng(11);
  WallHeadingConfig config;
  config.learn_scans = 5;
  WallHeading walls(config);
  const double heading = 0.3;
  for (int i = 0; i < config.learn_scans; ++i) {
    EXPECT_FALSE(walls.Measure(RoomCorner(heading, &rng), heading).has_value());
  }
  ASSERT_TRUE(walls.axes_known());
  EXPECT_NEAR(WrapQuarter(walls.axes_rad()), 0.0, kScanTolerance);

  // The robot is at 0.32 rad; the estimate says 0.30.
  const auto measured = walls.Measure(RoomCorner(0.32, &rng), 0.30);
  ASSERT_TRUE(measured.has_value());
  EXPECT_NEAR(*measured, 0.32, kScanTolerance);
  // A quarter turn on, the same.
  const auto turned = walls.Measure(RoomCorner(0.32 + M_PI / 2.0, &rng), 0.30 + M_PI / 2.0);
  ASSERT_TRUE(turned.has_value());
  EXPECT_NEAR(*turned, 0.32 + M_PI / 2.0, kScanTolerance);
  // In a wing at 30° to the axes the walls lie outside the gate.
  EXPECT_FALSE(walls.Measure(RoomCorner(0.32 - 30.0 * kDegree, &rng), 0.32).has_value());
}

}  // namespace
}  // namespace dynamap::mapping
