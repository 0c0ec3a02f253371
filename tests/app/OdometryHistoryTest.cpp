#include "dynamap/app/runtime/OdometryHistory.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dynamap::app::runtime {
namespace {

TEST(OdometryHistory, IntegratesStraightDrivingAndInterpolatesBetweenReadings) {
  mapping::MotionModelConfig config;
  config.use_gyro = false;
  OdometryHistory history(config, 10.0);
  std::vector<robotio::OdometryReading> odometry;
  for (int i = 0; i <= 50; ++i) odometry.push_back({i * 20'000'000LL, 0.01 * i, 0.01 * i});
  history.Add(odometry, {});
  const auto end = history.Latest();
  ASSERT_TRUE(end.has_value());
  EXPECT_NEAR(end->pose.x, 0.5, 1e-9);
  EXPECT_NEAR(end->pose.y, 0.0, 1e-9);
  const auto middle = history.PoseAt(510'000'000LL);  // Between readings 25 and 26.
  ASSERT_TRUE(middle.has_value());
  EXPECT_NEAR(middle->x, 0.255, 1e-9);
  EXPECT_NEAR(history.distance_m(), 0.5, 1e-9);
}

TEST(OdometryHistory, HeadingFollowsTheGyroWhenItIsThere) {
  mapping::MotionModelConfig config;
  OdometryHistory history(config, 10.0);
  std::vector<robotio::ImuReading> imu;
  for (int i = 0; i <= 200; ++i) imu.push_back({i * 10'000'000LL, 0.0, 0.0, 0.5});
  std::vector<robotio::OdometryReading> odometry;
  // Wheels say "straight"; the gyro says 0.5 rad/s for 2 s.
  for (int i = 0; i <= 100; ++i) odometry.push_back({i * 20'000'000LL, 0.0, 0.0});
  history.Add(odometry, imu);
  EXPECT_NEAR(history.Latest()->pose.theta, 1.0, 1e-6);
}

TEST(OdometryHistory, HasNoPoseBeforeTheFirstReading) {
  OdometryHistory history(mapping::MotionModelConfig{}, 1.0);
  EXPECT_FALSE(history.PoseAt(0).has_value());
}

}  // namespace
}  // namespace dynamap::app::runtime
