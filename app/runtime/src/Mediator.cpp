#include "dynamap/app/runtime/Mediator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

namespace dynamap::app::runtime {

namespace {
constexpr double kTrailSpacingM = 0.1;  // Trail points closer than this are not kept.
}  // namespace

Mediator::Mediator(double speed, mapping::MotionModelConfig motion)
    : clock(speed), odometry(motion, 30.0) {}

robotio::Pose2D Mediator::CurrentPose() const {
  const auto latest = odometry.Latest();
  const auto fix = pose_fix.Get();
  if (!latest) return fix ? fix->value.T_map_base : robotio::Pose2D{};
  if (!fix) return latest->pose;  // Before the first fix the map frame is the odometry's.
  const robotio::Pose2D since = fix->value.T_odom_base.Between(latest->pose);
  return fix->value.T_map_base.Compose(since);
}

void Mediator::ReportObstacles(const std::vector<Eigen::Vector2d>& points_map) {
  std::lock_guard<std::mutex> lock(obstacles_mutex_);
  obstacles_.insert(obstacles_.end(), points_map.begin(), points_map.end());
}

std::vector<Eigen::Vector2d> Mediator::TakeObstacles() {
  std::lock_guard<std::mutex> lock(obstacles_mutex_);
  std::vector<Eigen::Vector2d> out;
  out.swap(obstacles_);
  return out;
}

namespace {

// The true position at `stamp_ns`, interpolated between the poses around it; nullopt
// outside the truth recorded so far.
std::optional<Eigen::Vector3d> TruePositionAt(const robotio::Trajectory& truth,
                                              std::int64_t stamp_ns) {
  const auto after = std::lower_bound(
      truth.begin(), truth.end(), stamp_ns,
      [](const robotio::StampedPose& p, std::int64_t stamp) { return p.stamp_ns < stamp; });
  if (after == truth.end() || (after == truth.begin() && after->stamp_ns != stamp_ns)) {
    return std::nullopt;
  }
  if (after->stamp_ns == stamp_ns) return after->pose.translation();
  const auto before = after - 1;
  const double w = static_cast<double>(stamp_ns - before->stamp_ns) /
                   static_cast<double>(after->stamp_ns - before->stamp_ns);
  return (1.0 - w) * before->pose.translation() + w * after->pose.translation();
}

}  // namespace

void Mediator::AddEstimate(const robotio::StampedPose& pose) {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  estimates_.push_back(pose);
  if (const auto truth = TruePositionAt(ground_truth_, pose.stamp_ns)) {
    live_squared_error_ += (pose.pose.translation() - *truth).squaredNorm();
    ++live_error_count_;
  }
  const robotio::Pose2D p = robotio::Pose2D::FromIsometry(pose.pose);
  if (trail_.empty() || std::hypot(p.x - trail_.back().x, p.y - trail_.back().y) > kTrailSpacingM) {
    trail_.push_back(p);
  }
}

void Mediator::AddOdometryEstimate(const robotio::StampedPose& pose) {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  odometry_estimates_.push_back(pose);
}

robotio::Trajectory Mediator::OdometryEstimates() const {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  return odometry_estimates_;
}

void Mediator::AddGroundTruth(const std::vector<robotio::StampedPose>& poses) {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  ground_truth_.insert(ground_truth_.end(), poses.begin(), poses.end());
}

robotio::Trajectory Mediator::Estimates() const {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  return estimates_;
}

std::optional<double> Mediator::LiveAte() const {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  if (live_error_count_ == 0) return std::nullopt;
  return std::sqrt(live_squared_error_ / static_cast<double>(live_error_count_));
}

robotio::Trajectory Mediator::GroundTruth() const {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  return ground_truth_;
}

std::vector<robotio::Pose2D> Mediator::Trail() const {
  std::lock_guard<std::mutex> lock(trajectory_mutex_);
  return trail_;
}

bool Mediator::WaitForWorkers(std::int64_t t_ns, double control_period_s,
                              double replan_period_s) {
  const auto control_lag = static_cast<std::int64_t>(control_period_s * 1e9);
  const auto plan_lag = static_cast<std::int64_t>(replan_period_s * 1e9);
  while (!control.stopping()) {
    const bool control_ok = counters.control_done_ns.load() >= t_ns - control_lag;
    const bool slam_ok = counters.slam_done_ns.load() >= counters.last_frame_received_ns.load();
    const bool plan_ok = counters.planning_done_ns.load() >= t_ns - plan_lag;
    if (control_ok && slam_ok && plan_ok) return true;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return false;
}

void Mediator::WakeAll() {
  control.Stop();
  frames.Close();
  clock.WakeAll();
  plan.WakeAll();
  grid.WakeAll();
}

}  // namespace dynamap::app::runtime
