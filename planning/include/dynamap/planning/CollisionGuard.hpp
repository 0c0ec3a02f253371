// Reactive collision guard (thesis 7.1): checks the latest raw depth frames of both
// Kinects (not the map, which lags and filters people out of the static channel) for
// anything inside the footprint plus stopping distance, stops at once, then backs off or
// turns away, and names the obstacle so the planner can treat it as a temporary obstacle.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::planning {

struct CollisionGuardConfig {
  double footprint_radius_m = 0.36;  // m, base frame circle that must stay free.
  double safety_margin_m = 0.05;     // m added to the footprint.
  double min_height_m = 0.05;        // m, base z: lower points are floor (noise included).
  double max_height_m = 0.95;        // m, base z: robot height plus a margin.
  double max_decel_mps2 = 0.8;       // m/s², braking assumed for the stopping distance.
  double reaction_time_s = 0.2;      // s, frame age + command latency driven blind.
  int min_points = 15;               // Points needed to believe an obstacle (noise rejection).
  int pixel_stride = 2;              // Every n-th pixel in u and v is checked (speed).
  double backoff_speed_mps = 0.15;   // m/s, reverse speed after a stop when turning is unsafe.
  double turn_rate_radps = 0.6;      // rad/s, turn-away rate after a stop.
  double report_range_m = 1.5;       // m from the base origin: band points this near are
                                     // handed to the planner as temporary obstacles.
};

struct GuardVerdict {
  bool stop = false;                        // Command zero velocity now.
  int points_inside = 0;                    // Points in the protected zone (this check).
  double nearest_m = 0.0;                   // m from the footprint edge to the nearest such point.
  std::vector<Eigen::Vector2d> obstacle_base;  // On a stop: band points (x, y in base) within
                                               // the report range, for the planner.
  robotio::VelocityCommand recovery;        // What to do after stopping: turn or back off.
};

// Stopping distance at forward speed v: reaction travel plus braking.
[[nodiscard]] double StoppingDistance(double v_mps, const CollisionGuardConfig& config);

// The points of `frame` (taken with `rig`'s mounts) at robot height (config's height band,
// every pixel_stride-th pixel), as x, y in base, within `range_m` of the base origin. An
// invalid frame or one of a Kinect the rig does not have gives none.
[[nodiscard]] std::vector<Eigen::Vector2d> RobotHeightPoints(const robotio::DepthFrame& frame,
                                                             const robotio::Rig& rig,
                                                             const CollisionGuardConfig& config,
                                                             double range_m);

// Checks the frames (any number; one per Kinect) taken with `rig`'s mounts, while the base
// moves with `command`. Pure: the runtime keeps the latest frame per Kinect.
[[nodiscard]] GuardVerdict CheckCollision(const std::vector<const robotio::DepthFrame*>& frames,
                                          const robotio::Rig& rig,
                                          const robotio::VelocityCommand& command,
                                          const CollisionGuardConfig& config);
// The same check on robot-height points already taken out of the frames (RobotHeightPoints
// with a range of at least the report range and the protected zone's reach).
[[nodiscard]] GuardVerdict CheckCollisionPoints(const std::vector<Eigen::Vector2d>& points_base,
                                                const robotio::VelocityCommand& command,
                                                const CollisionGuardConfig& config);

}  // namespace dynamap::planning
