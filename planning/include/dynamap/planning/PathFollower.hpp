// Path following for the differential-drive base (thesis 7.2): (v, ω) towards a lookahead
// point on the shortened path, within the base's speed and acceleration limits, slower in
// turns and near obstacles, stopping within a tolerance of the goal.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"

namespace dynamap::planning {

struct PathFollowerConfig {
  double max_speed_mps = 1.0;          // m/s, base limit (segway_rmp50.yaml).
  double max_yaw_rate_radps = 1.5;     // rad/s, base limit.
  double max_accel_mps2 = 0.8;         // m/s², base limit, also used for braking to the goal.
  double max_yaw_accel_radps2 = 3.0;   // rad/s², base limit.
  double lookahead_m = 0.6;            // m along the path ahead of the robot's projection ...
  double min_lookahead_m = 0.15;       // m, ... shrinking to this plus the clearance in tight
                                       // places, so turns behind doorways are not cut.
  double heading_gain = 2.0;           // 1/s, ω = gain · heading error (before limits).
  double turn_in_place_rad = 0.8;      // rad, above this heading error the robot only turns.
  double slow_clearance_m = 0.6;       // m, below this clearance the speed scales down ...
  double stop_clearance_m = 0.05;      // m, ... reaching creep_speed_mps at this clearance.
  double creep_speed_mps = 0.1;        // m/s, slowest forward speed on a clear heading: the
                                       // grid's clearance is quantised to cells and reads 0-5 cm
                                       // in a doorway the robot fits through; the collision
                                       // guard, not the follower, stops for real contact.
  double goal_tolerance_m = 0.15;      // m, goal reached within this distance.
  double face_tolerance_rad = 0.2;     // rad, at the goal the robot turns in place until it
                                       // faces the path's look-at point this well.
};

struct FollowerOutput {
  robotio::VelocityCommand command;  // v, ω (stamp left to the caller).
  bool goal_reached = false;          // At the goal (and facing the look-at point, if any).
  bool facing = false;                // At the goal, turning towards the look-at point.
  double cross_track_m = 0.0;        // m, distance from the path (for monitoring).
};

class PathFollower {
 public:
  explicit PathFollower(PathFollowerConfig config = {}) : config_(config) {}

  // Waypoints in the map frame (m), e.g. the shortened planner path's cell centres, and
  // the point to face once there (what the viewpoint was chosen to see).
  void SetPath(std::vector<Eigen::Vector2d> waypoints,
               std::optional<Eigen::Vector2d> look_at = std::nullopt);
  // One control step: `clearance_m` is the free distance from the footprint's edge to the
  // nearest obstacle (cost field), `dt_s` the time since the previous step.
  [[nodiscard]] FollowerOutput Step(const robotio::Pose2D& pose, double clearance_m, double dt_s);
  void Stop() { last_ = {}; }

  [[nodiscard]] const PathFollowerConfig& config() const { return config_; }
  [[nodiscard]] const std::vector<Eigen::Vector2d>& path() const { return path_; }

 private:
  PathFollowerConfig config_;
  std::vector<Eigen::Vector2d> path_;
  std::optional<Eigen::Vector2d> look_at_;  // Cleared once faced.
  std::size_t segment_ = 0;          // Index of the segment the robot was last projected on.
  robotio::VelocityCommand last_;    // Previous command, for the acceleration limits.
};

}  // namespace dynamap::planning
