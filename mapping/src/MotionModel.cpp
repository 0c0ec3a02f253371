#include "dynamap/mapping/MotionModel.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::mapping {
namespace {

using robotio::ImuReading;
using robotio::Pose2D;

// Advances `pose` by `distance` along an arc that turns by `dtheta`: the chord of a
// circular arc points along the mid heading and has length 2 r sin(dtheta / 2).
Pose2D AdvanceArc(const Pose2D& pose, double distance, double dtheta) {
  const double half = 0.5 * dtheta;
  const double chord =
      std::abs(half) < 1e-9 ? distance : distance * std::sin(half) / half;
  const double heading = pose.theta + half;
  return {pose.x + chord * std::cos(heading), pose.y + chord * std::sin(heading),
          robotio::WrapAngle(pose.theta + dtheta)};
}

}  // namespace

Pose2D DriveIncrement(double left_m, double right_m, std::int64_t t0_ns, std::int64_t t1_ns,
                      const std::vector<ImuReading>& imu, const MotionModelConfig& config) {
  const double distance = 0.5 * (left_m + right_m);
  const double wheel_dtheta = (right_m - left_m) / config.track_width_m;
  if (t1_ns <= t0_ns) return AdvanceArc(Pose2D{}, distance, wheel_dtheta);

  const double total_s = robotio::NanosToSeconds(t1_ns - t0_ns);
  const std::int64_t max_gap_ns = robotio::SecondsToNanos(config.max_gyro_gap_s);
  auto by_stamp = [](const ImuReading& r, std::int64_t t) { return r.stamp_ns < t; };
  // The sample in force at t0 is the last one at or before it.
  auto it = std::lower_bound(imu.begin(), imu.end(), t0_ns + 1, by_stamp);
  if (it != imu.begin()) --it;
  const bool gyro_usable = config.use_gyro && it != imu.end() &&
                           std::abs(it->stamp_ns - t0_ns) <= max_gap_ns;
  if (!gyro_usable) return AdvanceArc(Pose2D{}, distance, wheel_dtheta);

  // Sub-steps between gyro stamps; the distance of a sub-step is proportional to its time.
  Pose2D pose;
  std::int64_t t = t0_ns;
  while (t < t1_ns) {
    auto next = std::next(it);
    std::int64_t step_end = t1_ns;
    if (next != imu.end() && next->stamp_ns < t1_ns) step_end = std::max(next->stamp_ns, t);
    // Over a gap in the gyro stream the wheels give the heading rate instead.
    const bool stale = t - it->stamp_ns > max_gap_ns;
    const double rate = stale ? wheel_dtheta / total_s : it->wz - config.gyro_bias_rad_s;
    const double dt = robotio::NanosToSeconds(step_end - t);
    pose = AdvanceArc(pose, distance * dt / total_s, rate * dt);
    t = step_end;
    if (next != imu.end() && next->stamp_ns <= t) it = next;
  }
  // Wheels that stood still: a differential drive cannot turn then, and what the gyro
  // says is its noise and the part of its bias not (yet) taken out (0.003 rad/s unlearnt
  // turns the heading 0.09° in the half second it takes to learn). A faster rate is the
  // base being turned by something else (carried, pushed) and is followed.
  if (left_m == 0.0 && right_m == 0.0 &&
      std::abs(pose.theta) <= config.still_rate_rad_s * total_s) {
    return Pose2D{};
  }
  return pose;
}

GyroBiasEstimator::GyroBiasEstimator(const MotionModelConfig& config) : config_(config) {}

void GyroBiasEstimator::AddInterval(const robotio::OdometryReading& from,
                                    const robotio::OdometryReading& to,
                                    const std::vector<ImuReading>& imu) {
  if (!config_.learn_gyro_bias || to.stamp_ns <= from.stamp_ns) return;
  // Whole encoder ticks: a wheel that stood still reports exactly the same distance.
  if (to.left_m != from.left_m || to.right_m != from.right_m) return;
  auto by_stamp = [](const ImuReading& r, std::int64_t t) { return r.stamp_ns < t; };
  const auto begin = std::lower_bound(imu.begin(), imu.end(), from.stamp_ns + 1, by_stamp);
  const auto end = std::lower_bound(imu.begin(), imu.end(), to.stamp_ns + 1, by_stamp);
  if (begin == end) return;
  for (auto it = begin; it != end; ++it) {
    if (std::abs(it->wz) > config_.max_learnt_bias_rad_s) return;
  }
  for (auto it = begin; it != end; ++it) rate_sum_ += it->wz;
  samples_ += static_cast<std::size_t>(end - begin);
  still_s_ += robotio::NanosToSeconds(to.stamp_ns - from.stamp_ns);
}

double GyroBiasEstimator::bias_rad_s() const {
  if (!config_.learn_gyro_bias || samples_ == 0 || still_s_ < config_.min_still_s) {
    return config_.gyro_bias_rad_s;
  }
  return rate_sum_ / static_cast<double>(samples_);
}

Trajectory2D DeadReckon(const std::vector<robotio::OdometryReading>& odometry,
                        const std::vector<ImuReading>& imu, const MotionModelConfig& config) {
  Trajectory2D trajectory;
  if (odometry.empty()) return trajectory;
  trajectory.reserve(odometry.size());
  trajectory.push_back({odometry.front().stamp_ns, Pose2D{}});
  GyroBiasEstimator bias(config);
  MotionModelConfig current = config;
  for (std::size_t i = 1; i < odometry.size(); ++i) {
    const auto& a = odometry[i - 1];
    const auto& b = odometry[i];
    current.gyro_bias_rad_s = bias.bias_rad_s();
    const Pose2D delta = DriveIncrement(b.left_m - a.left_m, b.right_m - a.right_m,
                                        a.stamp_ns, b.stamp_ns, imu, current);
    trajectory.push_back({b.stamp_ns, trajectory.back().pose.Compose(delta)});
    bias.AddInterval(a, b, imu);
  }
  return trajectory;
}

Pose2D PoseAt(const Trajectory2D& trajectory, std::int64_t stamp_ns) {
  assert(!trajectory.empty());
  auto it = std::lower_bound(
      trajectory.begin(), trajectory.end(), stamp_ns,
      [](const StampedPose2D& p, std::int64_t t) { return p.stamp_ns < t; });
  if (it == trajectory.begin()) return trajectory.front().pose;
  if (it == trajectory.end()) return trajectory.back().pose;
  const auto& b = *it;
  const auto& a = *std::prev(it);
  if (b.stamp_ns == a.stamp_ns) return b.pose;
  const double s = static_cast<double>(stamp_ns - a.stamp_ns) /
                   static_cast<double>(b.stamp_ns - a.stamp_ns);
  return robotio::Interpolate(a.pose, b.pose, s);
}

}  // namespace dynamap::mapping
