#include "dynamap/calibration/BaseTrack.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dynamap::calibration {
namespace {

// A 100 Hz gyro sampling a yaw rate that ramps up at 2 rad/s²: the track's heading must
// follow the exact integral, not lag half a gyro period as holding each sample would
// (a lag the solver would take for a Kinect latency 5 ms short).
TEST(BaseTrack, HeadingFollowsARampingGyroWithoutLag) {
  constexpr double kAccel = 2.0;  // rad/s².
  std::vector<robotio::OdometryReading> odometry;
  std::vector<robotio::ImuReading> imu;
  for (int i = 0; i <= 100; ++i) {  // 1 s at 100 Hz; the wheels stand still.
    const auto stamp = static_cast<std::int64_t>(i) * 10'000'000;
    robotio::OdometryReading o;
    o.stamp_ns = stamp;
    odometry.push_back(o);
    robotio::ImuReading g;
    g.stamp_ns = stamp;
    g.wz = kAccel * i * 0.01;
    imu.push_back(g);
  }
  const BaseTrack track = BaseTrack::Build(odometry, imu, BaseTrackConfig{});
  ASSERT_FALSE(track.empty());
  for (const double t : {0.25, 0.5, 0.9}) {
    const double exact = 0.5 * kAccel * t * t;
    // One gyro period of lag would be off by kAccel * t * 0.005 (≥ 2.5 mrad here).
    EXPECT_NEAR(track.At(t, 1.0, 1.0).theta, exact, 2e-4) << "t = " << t;
  }
}

// Wheels and gyro agree on a constant turn: heading and position follow the circle.
TEST(BaseTrack, ArcFromWheelsAndGyro) {
  constexpr double kV = 0.3, kOmega = 0.5, kTrack = 0.5;
  std::vector<robotio::OdometryReading> odometry;
  std::vector<robotio::ImuReading> imu;
  for (int i = 0; i <= 200; ++i) {  // 2 s; odometry at 50 Hz, gyro at 100 Hz.
    const double t = i * 0.01;
    const auto stamp = static_cast<std::int64_t>(i) * 10'000'000;
    if (i % 2 == 0) {
      robotio::OdometryReading o;
      o.stamp_ns = stamp;
      o.left_m = (kV - kOmega * kTrack / 2) * t;
      o.right_m = (kV + kOmega * kTrack / 2) * t;
      odometry.push_back(o);
    }
    robotio::ImuReading g;
    g.stamp_ns = stamp;
    g.wz = kOmega;
    imu.push_back(g);
  }
  const BaseTrack track = BaseTrack::Build(odometry, imu, BaseTrackConfig{});
  const robotio::Pose2D end = track.At(2.0, 1.0, 1.0);
  EXPECT_NEAR(end.theta, kOmega * 2.0, 1e-9);
  EXPECT_NEAR(end.x, kV / kOmega * std::sin(1.0), 1e-5);
  EXPECT_NEAR(end.y, kV / kOmega * (1.0 - std::cos(1.0)), 1e-5);
}

}  // namespace
}  // namespace dynamap::calibration
