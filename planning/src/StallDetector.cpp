#include "dynamap/planning/StallDetector.hpp"

#include <algorithm>
#include <cmath>

namespace dynamap::planning {

bool StallDetector::Update(const robotio::Pose2D& pose, double commanded_v_mps, double dt_s) {
  t_s_ += std::max(0.0, dt_s);
  commanded_m_ += std::abs(commanded_v_mps) * std::max(0.0, dt_s);
  window_.push_back({t_s_, commanded_m_, {pose.x, pose.y}});
  const double start_s = t_s_ - config_.window_s + 1e-9;
  while (window_.size() > 1 && window_[1].t_s <= start_s) window_.pop_front();
  const Sample& first = window_.front();
  if (first.t_s > start_s) return false;  // Not a whole window yet.
  const double commanded_m = commanded_m_ - first.commanded_m;
  if (commanded_m < config_.min_commanded_m) return false;
  const Eigen::Vector2d now(pose.x, pose.y);
  if ((now - first.position).norm() >= config_.max_progress_fraction * commanded_m) return false;
  window_.clear();
  return true;
}

std::vector<Eigen::Vector2d> StallObstacle(const robotio::Pose2D& pose, double footprint_radius_m,
                                           double direction, double spread_rad, double gap_m) {
  std::vector<Eigen::Vector2d> points;
  const double r = footprint_radius_m + gap_m;
  const double heading = direction < 0.0 ? pose.theta + M_PI : pose.theta;
  constexpr int kSteps = 8;  // Points on either side of straight ahead.
  for (int i = -kSteps; i <= kSteps; ++i) {
    const double a = heading + spread_rad * i / kSteps;
    points.emplace_back(pose.x + r * std::cos(a), pose.y + r * std::sin(a));
  }
  return points;
}

}  // namespace dynamap::planning
