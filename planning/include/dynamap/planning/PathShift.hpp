// Keeps the footprint off what the Kinects just saw when the map pose is off the map
// (SLAM's error, a decimetre or more late in a mission): a path planned through the middle
// of a 0.9 m doorway leaves the 0.72 m footprint 9 cm a side, so such an error puts the base
// on a door post. The obstacles the robot saw lately (ObstacleMemory, placed by odometry
// relative to the base) are checked along the stretch of path around the robot; the path is
// shifted (in the map frame) to where the footprint clears them, and the follower and the
// map guard are handed the pose shifted back by as much, i.e. where the robot is relative to
// the map's obstacles. No shift while everything is at least `comfort_m` clear.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace dynamap::planning {

struct PathShiftConfig {
  bool enabled = true;
  double max_shift_m = 0.2;   // m, largest shift tried.
  double step_m = 0.02;       // m, grid of the shifts tried.
  double behind_m = 0.3;      // m of path behind the robot's projection checked ...
  double ahead_m = 1.0;       // m ... and ahead of it.
  double sample_m = 0.05;     // m between the footprint centres checked along the path.
  // m, clearance (beyond the footprint) worth shifting for: a 0.9 m door leaves 0.09 m a
  // side. With 0.1 a true-pose mission shifted its path by 0.2 m in a doorway.
  double comfort_m = 0.08;
  double shift_cost = 0.5;    // m of clearance a metre of shift costs (prefers small shifts).
  double min_gain_m = 0.01;   // m, a shift must gain this much over none (no dithering).
  double rate_mps = 0.2;      // m/s, how fast the applied shift follows its target.
};

// The shift (map frame) of the stretch of `path_map` around `robot_on_path` (the robot's
// position as the path sees it) that best trades clearance to `obstacles_map` (capped at
// comfort_m beyond `footprint_m`) against its size; zero when nothing is nearer than that,
// no shift gains min_gain_m, or the best still leaves something inside the footprint.
[[nodiscard]] Eigen::Vector2d PathShiftTarget(const std::vector<Eigen::Vector2d>& path_map,
                                              const Eigen::Vector2d& robot_on_path,
                                              const std::vector<Eigen::Vector2d>& obstacles_map,
                                              double footprint_m, const PathShiftConfig& config);

// The shift applied over time: follows PathShiftTarget at rate_mps.
class PathShift {
 public:
  explicit PathShift(PathShiftConfig config = {}) : config_(config) {}

  // `robot_map`: the robot's map position (SLAM's); returns the shift now in force.
  Eigen::Vector2d Update(const std::vector<Eigen::Vector2d>& path_map,
                         const Eigen::Vector2d& robot_map,
                         const std::vector<Eigen::Vector2d>& obstacles_map, double footprint_m,
                         double dt_s);
  [[nodiscard]] const Eigen::Vector2d& shift() const { return shift_; }
  [[nodiscard]] const PathShiftConfig& config() const { return config_; }

 private:
  PathShiftConfig config_;
  Eigen::Vector2d shift_ = Eigen::Vector2d::Zero();
};

}  // namespace dynamap::planning
