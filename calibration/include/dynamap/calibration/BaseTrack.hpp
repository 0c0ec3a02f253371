// The base's planar path from wheel odometry and gyro, kept linear in the two wheel scale
// factors so the calibration solver can re-scale it and shift it in time cheaply
// (thesis 5.2 / Algorithm 3 with the heading from the gyro).
#pragma once

#include <cstdint>
#include <vector>

#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"

namespace dynamap::calibration {

struct BaseTrackConfig {
  double sample_rate_hz = 200.0;   // Hz, uniform resampling rate of the track.
  double gyro_bias_rad_s = 0.0;    // rad/s about base z, subtracted from every yaw rate.
};

// On a uniform time grid: heading from the integrated gyro, and the position split into
// the parts each wheel contributes, so position(t) = s_l·left(t) + s_r·right(t) for true
// wheel distance = scale × reported distance.
class BaseTrack {
 public:
  // Odometry and gyro sorted by stamp; empty track when odometry has < 2 readings.
  [[nodiscard]] static BaseTrack Build(const std::vector<robotio::OdometryReading>& odometry,
                                       const std::vector<robotio::ImuReading>& imu,
                                       const BaseTrackConfig& config);

  [[nodiscard]] bool empty() const { return theta_.size() < 2; }
  [[nodiscard]] std::int64_t origin_ns() const { return origin_ns_; }
  [[nodiscard]] double rate_hz() const { return rate_hz_; }
  [[nodiscard]] int size() const { return static_cast<int>(theta_.size()); }
  // Seconds since origin_ns of a stamp.
  [[nodiscard]] double Seconds(std::int64_t stamp_ns) const;
  [[nodiscard]] double duration_s() const { return (size() - 1) / rate_hz_; }

  // Pose at t seconds after origin (linear interpolation, clamped to the covered time).
  [[nodiscard]] robotio::Pose2D At(double t_s, double scale_left, double scale_right) const;

  // Grid samples, interleaved per sample as [theta, left_x, left_y, right_x, right_y]
  // (what the solver's cubic interpolator reads).
  [[nodiscard]] const std::vector<double>& samples() const { return samples_; }
  // Reported cumulative wheel distances (m) at each grid sample, from the first reading.
  [[nodiscard]] const std::vector<double>& left_m() const { return left_m_; }
  [[nodiscard]] const std::vector<double>& right_m() const { return right_m_; }

 private:
  std::int64_t origin_ns_ = 0;
  double rate_hz_ = 200.0;
  std::vector<double> theta_;
  std::vector<double> samples_;
  std::vector<double> left_m_;
  std::vector<double> right_m_;
};

}  // namespace dynamap::calibration
