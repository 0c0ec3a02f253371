// A short memory of what the Kinects saw at robot height, kept in the odometry frame. Door
// posts and desk corners leave the Kinects' view (nothing nearer than 0.5 m, nothing beside
// or behind the base) just before the footprint passes them; dead reckoning over those few
// seconds is good to a centimetre or two, whereas the map pose SLAM gives control can be a
// decimetre or more off the map near a doorway. Remembered points are placed relative to the
// base by odometry alone, so they stay where they are relative to the robot whatever SLAM's
// error. A point is forgotten `keep_s` after it was last seen (people walking leave a trail
// that long).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::planning {

struct ObstacleMemoryConfig {
  double cell_m = 0.05;   // m, one remembered point (the newest) per cell of this size.
  double keep_s = 8.0;    // s after a cell was last seen that it is forgotten.
  double range_m = 2.5;   // m from the base: farther points are not remembered.
};

class ObstacleMemory {
 public:
  explicit ObstacleMemory(ObstacleMemoryConfig config = {});

  // Points (x, y in base) seen at `stamp_ns` with the base at `T_odom_base`.
  void Insert(const std::vector<Eigen::Vector2d>& points_base, const robotio::Pose2D& T_odom_base,
              std::int64_t stamp_ns);
  // Forgets the cells last seen more than keep_s before `now_ns`.
  void Forget(std::int64_t now_ns);
  // Remembered points within `radius_m` of the base at `T_odom_base`, as x, y in base.
  [[nodiscard]] std::vector<Eigen::Vector2d> PointsNear(const robotio::Pose2D& T_odom_base,
                                                        double radius_m) const;
  [[nodiscard]] std::size_t size() const { return cells_.size(); }
  [[nodiscard]] const ObstacleMemoryConfig& config() const { return config_; }

 private:
  struct Remembered {
    Eigen::Vector2d p_odom;
    std::int64_t stamp_ns = 0;
  };
  ObstacleMemoryConfig config_;
  std::unordered_map<std::uint64_t, Remembered> cells_;
};

}  // namespace dynamap::planning
