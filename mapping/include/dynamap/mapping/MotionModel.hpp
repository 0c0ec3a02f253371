// Dead reckoning of the planar base from cumulative wheel distances, with the heading taken
// from the higher-rate gyro (thesis 5.2, Algorithm 3, differential drive).
#pragma once

#include <cstdint>
#include <vector>

#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"

namespace dynamap::mapping {

struct MotionModelConfig {
  // Heading source: the gyro's yaw rate (thesis 5.2.2) or, when false or when no gyro
  // sample falls near an interval, the wheel difference divided by the track width.
  bool use_gyro = true;
  double track_width_m = 0.5;       // m, distance between the wheel contact points.
  double gyro_bias_rad_s = 0.0;     // rad/s, subtracted from every yaw rate (base z).
  // s, a gyro sample older than this is not held over a gap (then wheels give heading).
  double max_gyro_gap_s = 0.1;
  // Learn the bias while the wheels stand still: once min_still_s of standing still has
  // been seen, the mean gyro yaw rate over it replaces gyro_bias_rad_s (a 0.003 rad/s
  // bias, the simulated RMP's gyro, turns the heading 26° in 150 s).
  bool learn_gyro_bias = true;
  double min_still_s = 0.5;  // s.
  // rad/s: a still interval with a gyro sample further from zero is not counted (the
  // base was being turned by something else, not drifting).
  double max_learnt_bias_rad_s = 0.05;
  // rad/s: over an interval in which neither wheel moved, a mean gyro rate (less the bias)
  // within this is noise and unlearnt bias, and the heading stays; a faster one is followed.
  double still_rate_rad_s = 0.01;
};

// The gyro's yaw-rate bias from the odometry intervals in which neither wheel moved (a
// differential drive cannot turn then): the mean rate of the gyro samples in them.
class GyroBiasEstimator {
 public:
  explicit GyroBiasEstimator(const MotionModelConfig& config);
  // One odometry interval (from.stamp_ns, to.stamp_ns]; `imu` sorted by stamp, may hold
  // samples outside the interval.
  void AddInterval(const robotio::OdometryReading& from, const robotio::OdometryReading& to,
                   const std::vector<robotio::ImuReading>& imu);
  // The configured bias until min_still_s of standing still has been seen, then the
  // learnt one (always the configured one when learning is off).
  [[nodiscard]] double bias_rad_s() const;
  [[nodiscard]] double still_s() const { return still_s_; }

 private:
  MotionModelConfig config_;
  double still_s_ = 0.0;
  double rate_sum_ = 0.0;
  std::size_t samples_ = 0;
};

struct StampedPose2D {
  std::int64_t stamp_ns = 0;
  robotio::Pose2D pose;  // T_odom_base: the base in the frame of the first reading.
};
using Trajectory2D = std::vector<StampedPose2D>;

// One odometry interval [t0_ns, t1_ns]: the base's displacement expressed in its pose at
// t0. The wheel distance is spread evenly in time (constant speed within the interval);
// the heading follows the gyro samples, each yaw rate held until the next sample, so an
// arc comes out as a smooth curve rather than a chord. With neither wheel moving and the
// gyro within config.still_rate_rad_s, nothing moved. `imu` must be sorted by stamp.
[[nodiscard]] robotio::Pose2D DriveIncrement(double left_m, double right_m,
                                             std::int64_t t0_ns, std::int64_t t1_ns,
                                             const std::vector<robotio::ImuReading>& imu,
                                             const MotionModelConfig& config);

// The base pose at every odometry reading, starting at the identity at the first one.
// Both inputs sorted by stamp. The gyro bias is learnt as it goes (GyroBiasEstimator):
// each interval uses what the intervals before it showed.
[[nodiscard]] Trajectory2D DeadReckon(const std::vector<robotio::OdometryReading>& odometry,
                                      const std::vector<robotio::ImuReading>& imu,
                                      const MotionModelConfig& config);

// The pose at `stamp_ns` interpolated between the neighbouring entries; clamped to the
// first/last entry outside the covered time. `trajectory` must not be empty.
[[nodiscard]] robotio::Pose2D PoseAt(const Trajectory2D& trajectory, std::int64_t stamp_ns);

}  // namespace dynamap::mapping
