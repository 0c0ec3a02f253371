#include "dynamap/mapping/CameraTracker.hpp"

#include <chrono>
#include <cmath>
#include <utility>

#include "dynamap/mapping/Preprocessing.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::mapping {
namespace {

using Clock = std::chrono::steady_clock;
using Twist = Eigen::Matrix<double, 6, 1>;  // (translation, rotation vector).

double Since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

Twist Log(const Eigen::Isometry3d& delta) {
  const Eigen::AngleAxisd rotation(delta.rotation());
  Twist twist;
  twist.head<3>() = delta.translation();
  twist.tail<3>() = rotation.angle() * rotation.axis();
  return twist;
}

Eigen::Isometry3d Exp(const Twist& twist) {
  Eigen::Isometry3d delta = Eigen::Isometry3d::Identity();
  const double angle = twist.tail<3>().norm();
  if (angle > 1e-12) delta.linear() = Eigen::AngleAxisd(angle, twist.tail<3>() / angle).toRotationMatrix();
  delta.translation() = twist.head<3>();
  return delta;
}

double RotationAngle(const Eigen::Isometry3d& delta) {
  return Eigen::AngleAxisd(delta.rotation()).angle();
}

}  // namespace

CameraTracker::CameraTracker(CameraTrackerConfig config, robotio::Rig rig)
    : config_([&] {
        config.registration.planar = false;
        return config;
      }()),
      rig_(std::move(rig)),
      registration_(config_.registration) {}

Eigen::Isometry3d CameraTracker::Predict(std::int64_t stamp_ns) const {
  if (!last_stamp_ns_) return pose_;
  const double dt = robotio::NanosToSeconds(stamp_ns - *last_stamp_ns_);
  return pose_ * Exp(velocity_ * dt);
}

void CameraTracker::RebuildTarget() {
  robotio::PointList merged;
  for (const Keyframe& keyframe : local_map_) {
    merged.insert(merged.end(), keyframe.points_map.begin(), keyframe.points_map.end());
  }
  registration_.SetTarget(VoxelGridFilter(merged, config_.voxel_m));
}

TrackerStep CameraTracker::Track(const std::vector<robotio::DepthFrame>& frames) {
  TrackerStep step;
  if (frames.empty()) return step;
  step.stamp_ns = frames.front().stamp_ns;
  auto start = Clock::now();
  robotio::PointList points;
  for (const robotio::DepthFrame& frame : frames) {
    if (frame.sensor_id < 0 || frame.sensor_id >= static_cast<int>(rig_.kinects.size())) continue;
    const robotio::PointList base =
        robotio::DepthToBasePoints(frame, rig_.kinects[static_cast<std::size_t>(frame.sensor_id)]);
    points.insert(points.end(), base.begin(), base.end());
  }
  // Thinned on a grid fixed in the map at the predicted pose: a grid fixed to the camera
  // leaves a lattice of centroids that moves with it and pulls registration towards no
  // motion (SlamLoop does the same).
  step.predicted = Predict(step.stamp_ns);
  points = TransformedPoints(
      VoxelGridFilter(TransformedPoints(points, step.predicted), config_.voxel_m),
      step.predicted.inverse());
  step.scan_points = points.size();
  step.preprocess_s = Since(start);

  step.pose = step.predicted;
  if (!local_map_.empty()) {
    start = Clock::now();
    step.registration = registration_.Align(points, step.predicted);
    step.register_s = Since(start);
    step.registered = true;
    const Eigen::Isometry3d& corrected = step.registration.T_target_source;
    const Eigen::Isometry3d correction = step.predicted.inverse() * corrected;
    step.accepted = step.registration.converged &&
                    step.registration.inlier_ratio >= config_.min_inlier_ratio &&
                    step.registration.fitness_rmse_m <= config_.max_fitness_rmse_m &&
                    correction.translation().norm() <= config_.max_correction_m &&
                    RotationAngle(correction) <= config_.max_correction_rad;
    if (step.accepted) step.pose = corrected;
  }

  // Velocity from the last interval; a scan that was not registered keeps the old one.
  if (last_stamp_ns_ && step.stamp_ns > *last_stamp_ns_ && (step.accepted || !step.registered)) {
    const double dt = robotio::NanosToSeconds(step.stamp_ns - *last_stamp_ns_);
    velocity_ = Log(pose_.inverse() * step.pose) / dt;
  }
  pose_ = step.pose;
  last_stamp_ns_ = step.stamp_ns;

  rejections_in_a_row_ = step.registered && !step.accepted ? rejections_in_a_row_ + 1 : 0;
  if (rejections_in_a_row_ >= config_.restart_after_rejections) {
    local_map_.clear();
    velocity_.setZero();
    rejections_in_a_row_ = 0;
    step.restarted = true;
    ++restarts_;
  }
  const bool first = local_map_.empty();
  bool far = first;
  if (!first) {
    const Eigen::Isometry3d from_last = local_map_.back().pose.inverse() * pose_;
    far = from_last.translation().norm() >= config_.keyframe_distance_m ||
          RotationAngle(from_last) >= config_.keyframe_angle_rad;
  }
  // Only a scan whose pose is trusted may extend the map it is registered against.
  if (far && (first || step.accepted) && !points.empty()) {
    local_map_.push_back({pose_, TransformedPoints(points, pose_)});
    while (static_cast<int>(local_map_.size()) > config_.local_map_keyframes) local_map_.pop_front();
    ++keyframes_total_;
    step.keyframe = true;
    RebuildTarget();
  }
  return step;
}

}  // namespace dynamap::mapping
