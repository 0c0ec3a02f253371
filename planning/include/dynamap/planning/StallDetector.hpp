// Stall detection for the differential-drive base: the commands ask it to drive, the pose
// does not move. The Kinects see nothing within 0.5 m of them, so a door swinging shut
// against the base or a table edge pressed from the side reaches neither the collision
// guard nor the map; a stalled base is how the robot notices, as a bumper would. What
// blocks it is then drawn in front of the footprint (`StallObstacle`) for the planner.
#pragma once

#include <Eigen/Core>
#include <deque>
#include <vector>

#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::planning {

struct StallDetectorConfig {
  double window_s = 1.0;                // s of commands judged together.
  double min_commanded_m = 0.08;        // m the window's commands must ask for: creeping
                                        // and turning in place are never stalls.
  double max_progress_fraction = 0.25;  // A stall: the base moved less than this share of
                                        // what was commanded (acceleration lag stays well
                                        // above it).
};

class StallDetector {
 public:
  explicit StallDetector(StallDetectorConfig config = {}) : config_(config) {}

  // One control step: `commanded_v_mps` is the command in force over the last `dt_s`,
  // `pose` where the base is now. True once per stall: the window starts afresh after it.
  [[nodiscard]] bool Update(const robotio::Pose2D& pose, double commanded_v_mps, double dt_s);

 private:
  struct Sample {
    double t_s;                // Time since the detector started.
    double commanded_m;        // Sum of |v|·dt asked for up to then.
    Eigen::Vector2d position;  // Where the base was then.
  };
  StallDetectorConfig config_;
  double t_s_ = 0.0;
  double commanded_m_ = 0.0;
  std::deque<Sample> window_;  // From the last sample at least a window old to now.
};

// Points (map frame) on the arc of the footprint's edge facing the way the base was driving
// (`direction` +1 forward, -1 backward), `spread_rad` to either side, `gap_m` beyond the
// radius: where the unseen obstacle must be.
[[nodiscard]] std::vector<Eigen::Vector2d> StallObstacle(const robotio::Pose2D& pose,
                                                         double footprint_radius_m,
                                                         double direction,
                                                         double spread_rad = 0.7,
                                                         double gap_m = 0.03);

}  // namespace dynamap::planning
