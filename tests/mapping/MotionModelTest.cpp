#include "dynamap/mapping/MotionModel.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dynamap::mapping {
namespace {

using robotio::ImuReading;
using robotio::OdometryReading;
constexpr std::int64_t kMs = 1'000'000;

struct Drive {
  std::vector<OdometryReading> odometry;
  std::vector<ImuReading> imu;
};

// A base driving at (v, omega) for `seconds`: wheels at 50 Hz, gyro at 200 Hz,
// the gyro offset in time from the wheels as on the real robot.
Drive SimulateDrive(double v, double omega, double seconds, double track_width) {
  Drive drive;
  const double vl = v - 0.5 * track_width * omega;
  const double vr = v + 0.5 * track_width * omega;
  for (std::int64_t t = 0; t <= static_cast<std::int64_t>(seconds * 1000); t += 20)
    drive.odometry.push_back({t * kMs, vl * t * 1e-3, vr * t * 1e-3});
  for (std::int64_t t = 3; t <= static_cast<std::int64_t>(seconds * 1000); t += 5)
    drive.imu.push_back({t * kMs, 0.0, 0.0, omega});
  return drive;
}

TEST(MotionModel, StraightLineMovesAlongHeading) {
  const Drive drive = SimulateDrive(0.5, 0.0, 4.0, 0.5);
  const Trajectory2D trajectory = DeadReckon(drive.odometry, drive.imu, {});
  const auto& end = trajectory.back().pose;
  EXPECT_NEAR(end.x, 2.0, 1e-9);
  EXPECT_NEAR(end.y, 0.0, 1e-9);
  EXPECT_NEAR(end.theta, 0.0, 1e-12);
}

TEST(MotionModel, QuarterArcEndsOnCircle) {
  // Radius 1 m, a quarter turn: from (0,0) heading +x to (1,1) heading +y.
  const double omega = M_PI / 2.0 / 4.0;
  const Drive drive = SimulateDrive(omega * 1.0, omega, 4.0, 0.5);
  const auto& end = DeadReckon(drive.odometry, drive.imu, {}).back().pose;
  EXPECT_NEAR(end.x, 1.0, 1e-6);
  EXPECT_NEAR(end.y, 1.0, 1e-6);
  EXPECT_NEAR(end.theta, M_PI / 2.0, 1e-9);
}

TEST(MotionModel, HeadingComesFromGyroNotWheels) {
  // Wheel slip: the wheels report a straight line while the gyro sees a turn.
  Drive drive = SimulateDrive(0.4, 0.0, 2.0, 0.5);
  for (auto& sample : drive.imu) sample.wz = 0.3;
  const auto& end = DeadReckon(drive.odometry, drive.imu, {}).back().pose;
  EXPECT_NEAR(end.theta, 0.6, 1e-9);
  MotionModelConfig wheels_only;
  wheels_only.use_gyro = false;
  EXPECT_NEAR(DeadReckon(drive.odometry, drive.imu, wheels_only).back().pose.theta, 0.0, 1e-12);
}

TEST(MotionModel, SpinInPlaceKeepsPosition) {
  const Drive drive = SimulateDrive(0.0, 1.0, 3.0, 0.5);
  const auto& end = DeadReckon(drive.odometry, drive.imu, {}).back().pose;
  EXPECT_NEAR(end.x, 0.0, 1e-12);
  EXPECT_NEAR(end.y, 0.0, 1e-12);
  EXPECT_NEAR(end.theta, robotio::WrapAngle(3.0), 1e-9);
}

TEST(MotionModel, WheelsAloneIntegrateArcWithoutGyro) {
  const double omega = 0.5;
  const Drive drive = SimulateDrive(0.5, omega, 2.0, 0.6);
  MotionModelConfig config;
  config.use_gyro = false;
  config.track_width_m = 0.6;
  const auto& end = DeadReckon(drive.odometry, {}, config).back().pose;
  // Radius 1 m, turned 1 rad.
  EXPECT_NEAR(end.x, std::sin(1.0), 1e-9);
  EXPECT_NEAR(end.y, 1.0 - std::cos(1.0), 1e-9);
  EXPECT_NEAR(end.theta, 1.0, 1e-9);
}

TEST(MotionModel, GyroBiasIsRemoved) {
  Drive drive = SimulateDrive(0.0, 0.0, 2.0, 0.5);
  for (auto& sample : drive.imu) sample.wz = 0.01;
  MotionModelConfig config;
  config.gyro_bias_rad_s = 0.01;
  EXPECT_NEAR(DeadReckon(drive.odometry, drive.imu, config).back().pose.theta, 0.0, 1e-12);
}

// The robot stands 1 s, then drives straight 4 s with a gyro biased by 0.003 rad/s: the
// bias learnt while standing keeps the heading (26° in 150 s if left in), and while the
// wheels stand still the heading stays, the bias learnt or not.
TEST(MotionModel, GyroBiasIsLearntWhileTheWheelsStandStill) {
  constexpr double kBias = 0.003;
  Drive drive;
  for (std::int64_t t = 0; t <= 5000; t += 20) {
    const double driven = t <= 1000 ? 0.0 : 0.5 * (t - 1000) * 1e-3;
    drive.odometry.push_back({t * kMs, driven, driven});
  }
  for (std::int64_t t = 3; t <= 5000; t += 5) {
    // ±0.004 rad/s of alternating noise around the bias.
    drive.imu.push_back({t * kMs, 0.0, 0.0, kBias + ((t / 5) % 2 == 0 ? 0.004 : -0.004)});
  }
  MotionModelConfig config;
  const Trajectory2D learnt = DeadReckon(drive.odometry, drive.imu, config);
  // Standing, nothing turns (the first 0.5 s ran on the configured bias, 0, and turned the
  // heading 1.5 mrad); driving, the learnt bias is taken out.
  EXPECT_NEAR(learnt[50].pose.theta, 0.0, 1e-12);
  EXPECT_NEAR(learnt.back().pose.theta, 0.0, 1e-4);
  config.learn_gyro_bias = false;
  const Trajectory2D fixed = DeadReckon(drive.odometry, drive.imu, config);
  EXPECT_NEAR(fixed[50].pose.theta, 0.0, 1e-12);
  EXPECT_NEAR(fixed.back().pose.theta, 4.0 * kBias, 3e-4);
  // Sideways drift over the 2 m: 6 mm with the bias left in.
  EXPECT_LT(std::abs(learnt.back().pose.y), 0.05 * std::abs(fixed.back().pose.y));

  GyroBiasEstimator estimator(MotionModelConfig{});
  for (std::size_t i = 1; i < drive.odometry.size(); ++i) {
    estimator.AddInterval(drive.odometry[i - 1], drive.odometry[i], drive.imu);
  }
  EXPECT_NEAR(estimator.still_s(), 1.0, 1e-9);
  EXPECT_NEAR(estimator.bias_rad_s(), kBias, 1e-4);

  // Still wheels under a turning gyro (the base carried round) teach no bias.
  for (auto& sample : drive.imu) sample.wz = 0.5;
  GyroBiasEstimator carried(MotionModelConfig{});
  for (std::size_t i = 1; i < drive.odometry.size(); ++i) {
    carried.AddInterval(drive.odometry[i - 1], drive.odometry[i], drive.imu);
  }
  EXPECT_EQ(carried.still_s(), 0.0);
  EXPECT_EQ(carried.bias_rad_s(), 0.0);
  // ... and the heading follows the gyro round: 0.5 rad/s over the first second.
  EXPECT_NEAR(DeadReckon(drive.odometry, drive.imu, MotionModelConfig{})[50].pose.theta, 0.5,
              0.01);
}

TEST(MotionModel, PoseAtInterpolatesBetweenReadings) {
  const Drive drive = SimulateDrive(1.0, 0.0, 1.0, 0.5);
  const Trajectory2D trajectory = DeadReckon(drive.odometry, drive.imu, {});
  EXPECT_NEAR(PoseAt(trajectory, 505 * kMs).x, 0.505, 1e-9);
  EXPECT_NEAR(PoseAt(trajectory, -5 * kMs).x, 0.0, 1e-12);
  EXPECT_NEAR(PoseAt(trajectory, 5000 * kMs).x, 1.0, 1e-9);
}

}  // namespace
}  // namespace dynamap::mapping
