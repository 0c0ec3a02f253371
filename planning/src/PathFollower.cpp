#include "dynamap/planning/PathFollower.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynamap::planning {

namespace {

double Clamp(double v, double lo, double hi) { return std::min(hi, std::max(lo, v)); }

}  // namespace

void PathFollower::SetPath(std::vector<Eigen::Vector2d> waypoints,
                           std::optional<Eigen::Vector2d> look_at) {
  path_ = std::move(waypoints);
  look_at_ = look_at;
  segment_ = 0;
}

FollowerOutput PathFollower::Step(const robotio::Pose2D& pose, double clearance_m, double dt_s) {
  FollowerOutput out;
  const Eigen::Vector2d p(pose.x, pose.y);
  if (path_.empty() || (p - path_.back()).norm() <= config_.goal_tolerance_m) {
    if (!path_.empty() && look_at_ && (*look_at_ - p).norm() > config_.goal_tolerance_m) {
      const Eigen::Vector2d to = *look_at_ - p;
      const double error = robotio::WrapAngle(std::atan2(to.y(), to.x()) - pose.theta);
      if (std::abs(error) > config_.face_tolerance_rad) {
        double omega = Clamp(config_.heading_gain * error, -config_.max_yaw_rate_radps,
                             config_.max_yaw_rate_radps);
        if (dt_s > 0.0) {
          omega = Clamp(omega, last_.omega - config_.max_yaw_accel_radps2 * dt_s,
                        last_.omega + config_.max_yaw_accel_radps2 * dt_s);
        }
        out.command.omega = omega;
        out.facing = true;
        last_ = out.command;
        return out;
      }
    }
    look_at_.reset();
    out.goal_reached = !path_.empty();
    last_ = {};
    return out;
  }
  // Project the robot on the path, never going back to earlier segments (the path may
  // return near itself).
  double best = std::numeric_limits<double>::infinity();
  std::size_t seg = segment_;
  double seg_t = 0.0;
  for (std::size_t i = segment_; i + 1 < path_.size(); ++i) {
    const Eigen::Vector2d a = path_[i];
    const Eigen::Vector2d ab = path_[i + 1] - a;
    const double len2 = ab.squaredNorm();
    const double t = len2 > 0.0 ? Clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
    const double d = (a + t * ab - p).norm();
    if (d < best) {
      best = d;
      seg = i;
      seg_t = t;
    }
  }
  segment_ = seg;
  out.cross_track_m = path_.size() > 1 ? best : (p - path_[0]).norm();
  // Lookahead point: walk lookahead_m along the path from the projection.
  Eigen::Vector2d target = path_.back();
  double remaining = std::clamp(config_.min_lookahead_m + std::max(0.0, clearance_m),
                                config_.min_lookahead_m,
                                std::max(config_.min_lookahead_m, config_.lookahead_m));
  if (path_.size() > 1) {
    Eigen::Vector2d from = path_[seg] + seg_t * (path_[seg + 1] - path_[seg]);
    for (std::size_t i = seg; i + 1 < path_.size(); ++i) {
      const double len = (path_[i + 1] - from).norm();
      if (len >= remaining) {
        target = from + remaining * (path_[i + 1] - from) / len;
        break;
      }
      remaining -= len;
      from = path_[i + 1];
    }
  }
  const Eigen::Vector2d to_target = target - p;
  const double heading_error =
      robotio::WrapAngle(std::atan2(to_target.y(), to_target.x()) - pose.theta);
  // Speed: full on straight, clear stretches; lower with the heading error, the clearance
  // and the distance left to brake before the goal.
  double v = config_.max_speed_mps;
  if (std::abs(heading_error) >= config_.turn_in_place_rad) {
    v = 0.0;
  } else {
    v *= std::cos(heading_error * (M_PI / 2.0) / config_.turn_in_place_rad);
  }
  const double span = std::max(1e-6, config_.slow_clearance_m - config_.stop_clearance_m);
  const double creep =
      std::min(1.0, config_.creep_speed_mps / std::max(1e-6, config_.max_speed_mps));
  v *= Clamp((clearance_m - config_.stop_clearance_m) / span, creep, 1.0);
  // Brake so that the speed is down to what one step may shed when the goal tolerance is
  // reached, where the command drops to zero. The braking curve assumes half the base's
  // deceleration: commands act a step late, and the full-deceleration curve overshoots.
  const double to_goal = (path_.back() - p).norm() - config_.goal_tolerance_m;
  const double last_step = dt_s > 0.0 ? config_.max_accel_mps2 * dt_s : 0.05;
  v = std::min(v, std::max(last_step, std::sqrt(config_.max_accel_mps2 * std::max(0.0, to_goal))));
  double omega = Clamp(config_.heading_gain * heading_error, -config_.max_yaw_rate_radps,
                       config_.max_yaw_rate_radps);
  // Acceleration limits relative to the previous command.
  if (dt_s > 0.0) {
    v = Clamp(v, last_.v - config_.max_accel_mps2 * dt_s, last_.v + config_.max_accel_mps2 * dt_s);
    omega = Clamp(omega, last_.omega - config_.max_yaw_accel_radps2 * dt_s,
                  last_.omega + config_.max_yaw_accel_radps2 * dt_s);
  }
  out.command.v = Clamp(v, 0.0, config_.max_speed_mps);
  out.command.omega = omega;
  last_ = out.command;
  return out;
}

}  // namespace dynamap::planning
