#include "dynamap/calibration/BaseTrack.hpp"

#include <algorithm>
#include <cmath>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::calibration {
namespace {

// Cumulative wheel distances at `t_ns`, linearly interpolated between readings.
std::pair<double, double> WheelsAt(const std::vector<robotio::OdometryReading>& odometry,
                                   std::int64_t t_ns) {
  auto it = std::lower_bound(
      odometry.begin(), odometry.end(), t_ns,
      [](const robotio::OdometryReading& r, std::int64_t t) { return r.stamp_ns < t; });
  if (it == odometry.begin()) return {it->left_m, it->right_m};
  if (it == odometry.end()) return {odometry.back().left_m, odometry.back().right_m};
  const auto& b = *it;
  const auto& a = *std::prev(it);
  const double s = b.stamp_ns == a.stamp_ns
                       ? 1.0
                       : static_cast<double>(t_ns - a.stamp_ns) /
                             static_cast<double>(b.stamp_ns - a.stamp_ns);
  return {a.left_m + s * (b.left_m - a.left_m), a.right_m + s * (b.right_m - a.right_m)};
}

// Gyro z rate at `t_ns`, from imu[i] (the last sample at or before it) and the next one.
double RateAt(const std::vector<robotio::ImuReading>& imu, std::size_t i, std::int64_t t_ns) {
  if (i + 1 >= imu.size() || imu[i].stamp_ns >= t_ns) return imu[i].wz;
  const double s = static_cast<double>(t_ns - imu[i].stamp_ns) /
                   static_cast<double>(imu[i + 1].stamp_ns - imu[i].stamp_ns);
  return imu[i].wz + s * (imu[i + 1].wz - imu[i].wz);
}

}  // namespace

BaseTrack BaseTrack::Build(const std::vector<robotio::OdometryReading>& odometry,
                           const std::vector<robotio::ImuReading>& imu,
                           const BaseTrackConfig& config) {
  BaseTrack track;
  track.rate_hz_ = config.sample_rate_hz;
  if (odometry.size() < 2) return track;
  track.origin_ns_ = odometry.front().stamp_ns;
  const double duration = robotio::NanosToSeconds(odometry.back().stamp_ns - track.origin_ns_);
  const int n = static_cast<int>(std::floor(duration * config.sample_rate_hz)) + 1;
  const double dt = 1.0 / config.sample_rate_hz;
  track.theta_.resize(n);
  track.left_m_.resize(n);
  track.right_m_.resize(n);
  track.samples_.assign(static_cast<std::size_t>(n) * 5, 0.0);

  std::size_t imu_index = 0;
  double theta = 0.0;
  Eigen::Vector2d left = Eigen::Vector2d::Zero();
  Eigen::Vector2d right = Eigen::Vector2d::Zero();
  const auto [first_l, first_r] = WheelsAt(odometry, track.origin_ns_);
  double prev_l = first_l;
  double prev_r = first_r;
  for (int k = 0; k < n; ++k) {
    if (k > 0) {
      const std::int64_t t0 = track.origin_ns_ + robotio::SecondsToNanos((k - 1) * dt);
      const std::int64_t t1 = track.origin_ns_ + robotio::SecondsToNanos(k * dt);
      // Gyro rate at the step's midpoint, interpolated between the samples around it (each
      // sample is the rate at its stamp; holding the last one would lag half a period).
      const std::int64_t mid = t0 + (t1 - t0) / 2;
      while (imu_index + 1 < imu.size() && imu[imu_index + 1].stamp_ns <= mid) ++imu_index;
      const double rate = imu.empty() ? 0.0 : RateAt(imu, imu_index, mid) - config.gyro_bias_rad_s;
      const double dtheta = rate * dt;
      const auto [l, r] = WheelsAt(odometry, t1);
      // Each wheel moves the centre by half its distance along the mid-step heading.
      const double mid_heading = theta + 0.5 * dtheta;
      const Eigen::Vector2d dir(std::cos(mid_heading), std::sin(mid_heading));
      left += 0.5 * (l - prev_l) * dir;
      right += 0.5 * (r - prev_r) * dir;
      prev_l = l;
      prev_r = r;
      theta += dtheta;
    }
    track.theta_[k] = theta;
    track.left_m_[k] = prev_l - first_l;
    track.right_m_[k] = prev_r - first_r;
    double* s = &track.samples_[static_cast<std::size_t>(k) * 5];
    s[0] = theta;
    s[1] = left.x();
    s[2] = left.y();
    s[3] = right.x();
    s[4] = right.y();
  }
  return track;
}

double BaseTrack::Seconds(std::int64_t stamp_ns) const {
  return robotio::NanosToSeconds(stamp_ns - origin_ns_);
}

robotio::Pose2D BaseTrack::At(double t_s, double scale_left, double scale_right) const {
  if (empty()) return {};
  const double x = std::clamp(t_s * rate_hz_, 0.0, static_cast<double>(size() - 1));
  const int i = std::min(static_cast<int>(x), size() - 2);
  const double f = x - i;
  auto lerp = [&](int c) {
    return (1.0 - f) * samples_[static_cast<std::size_t>(i) * 5 + c] +
           f * samples_[static_cast<std::size_t>(i + 1) * 5 + c];
  };
  return {scale_left * lerp(1) + scale_right * lerp(3),
          scale_left * lerp(2) + scale_right * lerp(4), lerp(0)};
}

}  // namespace dynamap::calibration
