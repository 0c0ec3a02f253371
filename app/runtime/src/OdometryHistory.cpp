#include "dynamap/app/runtime/OdometryHistory.hpp"

#include <algorithm>
#include <cmath>

namespace dynamap::app::runtime {

OdometryHistory::OdometryHistory(mapping::MotionModelConfig config, double keep_s)
    : config_(config), bias_(config), keep_ns_(static_cast<std::int64_t>(keep_s * 1e9)) {}

void OdometryHistory::Add(const std::vector<robotio::OdometryReading>& odometry,
                          const std::vector<robotio::ImuReading>& imu) {
  std::lock_guard<std::mutex> lock(mutex_);
  imu_.insert(imu_.end(), imu.begin(), imu.end());
  for (const robotio::OdometryReading& reading : odometry) {
    if (!last_reading_) {
      last_reading_ = reading;
      poses_.push_back({reading.stamp_ns, robotio::Pose2D{}});
      continue;
    }
    const double left = reading.left_m - last_reading_->left_m;
    const double right = reading.right_m - last_reading_->right_m;
    // The gyro samples that cover this interval (plus one before, for the held rate).
    const auto first = std::lower_bound(
        imu_.begin(), imu_.end(), last_reading_->stamp_ns,
        [](const robotio::ImuReading& r, std::int64_t t) { return r.stamp_ns < t; });
    const auto begin = first == imu_.begin() ? first : first - 1;
    const std::vector<robotio::ImuReading> window(begin, imu_.end());
    mapping::MotionModelConfig current = config_;
    current.gyro_bias_rad_s = bias_.bias_rad_s();
    const robotio::Pose2D delta = mapping::DriveIncrement(
        left, right, last_reading_->stamp_ns, reading.stamp_ns, window, current);
    bias_.AddInterval(*last_reading_, reading, window);
    poses_.push_back({reading.stamp_ns, poses_.back().pose.Compose(delta)});
    distance_m_ += std::abs(0.5 * (left + right));
    last_reading_ = reading;
  }
  const std::int64_t newest = poses_.empty() ? 0 : poses_.back().stamp_ns;
  while (poses_.size() > 2 && poses_.front().stamp_ns < newest - keep_ns_) poses_.pop_front();
  while (imu_.size() > 2 && imu_.front().stamp_ns < newest - keep_ns_) imu_.pop_front();
}

std::optional<robotio::Pose2D> OdometryHistory::PoseAt(std::int64_t stamp_ns) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (poses_.empty()) return std::nullopt;
  if (stamp_ns <= poses_.front().stamp_ns) return poses_.front().pose;
  if (stamp_ns >= poses_.back().stamp_ns) return poses_.back().pose;
  const auto after = std::lower_bound(
      poses_.begin(), poses_.end(), stamp_ns,
      [](const mapping::StampedPose2D& p, std::int64_t t) { return p.stamp_ns < t; });
  const auto before = after - 1;
  const double s = static_cast<double>(stamp_ns - before->stamp_ns) /
                   static_cast<double>(after->stamp_ns - before->stamp_ns);
  return robotio::Interpolate(before->pose, after->pose, s);
}

std::optional<mapping::StampedPose2D> OdometryHistory::Latest() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (poses_.empty()) return std::nullopt;
  return poses_.back();
}

double OdometryHistory::gyro_bias_rad_s() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return bias_.bias_rad_s();
}

double OdometryHistory::distance_m() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return distance_m_;
}

}  // namespace dynamap::app::runtime
