#include "dynamap/planning/CollisionGuard.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynamap::planning {

double StoppingDistance(double v_mps, const CollisionGuardConfig& config) {
  const double v = std::abs(v_mps);
  return v * config.reaction_time_s + v * v / (2.0 * config.max_decel_mps2);
}

std::vector<Eigen::Vector2d> RobotHeightPoints(const robotio::DepthFrame& frame,
                                               const robotio::Rig& rig,
                                               const CollisionGuardConfig& config,
                                               double range_m) {
  std::vector<Eigen::Vector2d> points;
  if (!frame.Valid()) return points;
  if (frame.sensor_id < 0 || frame.sensor_id >= static_cast<int>(rig.kinects.size())) {
    return points;
  }
  const robotio::KinectMount& mount = rig.kinects[frame.sensor_id];
  const Eigen::Isometry3f T = mount.T_base_kinect.cast<float>();
  const robotio::Intrinsics& k = frame.intrinsics;
  const int stride = std::max(1, config.pixel_stride);
  const double range_squared = range_m * range_m;
  for (int v = 0; v < frame.height; v += stride) {
    for (int u = 0; u < frame.width; u += stride) {
      const std::uint16_t d = frame.At(u, v);
      if (d == 0) continue;
      const float z = static_cast<float>(d) * 0.001f;
      const Eigen::Vector3f p_optical(static_cast<float>((u - k.cx) / k.fx) * z,
                                      static_cast<float>((v - k.cy) / k.fy) * z, z);
      const Eigen::Vector3f p = T * p_optical;
      if (p.z() < config.min_height_m || p.z() > config.max_height_m) continue;
      const Eigen::Vector2d xy(p.x(), p.y());
      if (xy.squaredNorm() <= range_squared) points.push_back(xy);
    }
  }
  return points;
}

GuardVerdict CheckCollision(const std::vector<const robotio::DepthFrame*>& frames,
                            const robotio::Rig& rig, const robotio::VelocityCommand& command,
                            const CollisionGuardConfig& config) {
  std::vector<Eigen::Vector2d> points;
  for (const robotio::DepthFrame* frame : frames) {
    if (frame == nullptr) continue;
    const std::vector<Eigen::Vector2d> some =
        RobotHeightPoints(*frame, rig, config, std::numeric_limits<double>::infinity());
    points.insert(points.end(), some.begin(), some.end());
  }
  return CheckCollisionPoints(points, command, config);
}

GuardVerdict CheckCollisionPoints(const std::vector<Eigen::Vector2d>& points_base,
                                  const robotio::VelocityCommand& command,
                                  const CollisionGuardConfig& config) {
  GuardVerdict verdict;
  const double radius = config.footprint_radius_m + config.safety_margin_m;
  const double stop = StoppingDistance(command.v, config);
  const double direction = command.v < 0.0 ? -1.0 : 1.0;
  double nearest = std::numeric_limits<double>::infinity();
  double mean_y = 0.0;                     // Of the zone points: which side the obstacle is on.
  std::vector<Eigen::Vector2d> nearby;     // Points within the report range.
  for (const Eigen::Vector2d& p : points_base) {
    const double distance = p.norm();
    if (distance <= config.report_range_m) nearby.push_back(p);
    // Protected zone: the footprint circle, plus the corridor the footprint sweeps over
    // the stopping distance in the direction of travel.
    const double along = direction * p.x();
    const double lateral = std::abs(p.y());
    const bool in_circle = distance <= radius;
    const bool in_corridor = along > 0.0 && along <= radius + stop && lateral <= radius;
    if (!in_circle && !in_corridor) continue;
    ++verdict.points_inside;
    nearest = std::min(nearest, distance - config.footprint_radius_m);
    mean_y += p.y();
  }
  if (verdict.points_inside < config.min_points) return verdict;
  verdict.stop = true;
  // The planner gets the whole nearby obstacle, not only the sliver inside the zone, so the
  // replanned path keeps clear of all of it.
  verdict.obstacle_base = std::move(nearby);
  mean_y /= verdict.points_inside;
  verdict.nearest_m = std::max(0.0, nearest);
  // Turn away from the side the obstacle is on; when it is dead ahead and already inside
  // the footprint circle, back off first (the Kinects look forward, so reversing a short
  // way over ground just driven is the safer blind move).
  if (verdict.nearest_m <= config.safety_margin_m && std::abs(mean_y) < 0.1) {
    verdict.recovery.v = -direction * config.backoff_speed_mps;
  } else {
    verdict.recovery.omega = mean_y >= 0.0 ? -config.turn_rate_radps : config.turn_rate_radps;
  }
  return verdict;
}

}  // namespace dynamap::planning
