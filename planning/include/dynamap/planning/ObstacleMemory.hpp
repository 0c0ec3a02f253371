// A short memory of what the Kinects saw at robot height, kept in the odometry frame. Door
// posts and desk corners leave the Kinects' view (nothing nearer than 0.5 m, nothing beside
// or behind the base) just before the footprint passes them; dead reckoning over those few
// seconds is good to a centimetre or two, whereas the map pose SLAM gives control can be a
// decimetre or more off the map near a doorway. Remembered points are placed relative to the
// base by odometry alone, so they stay where they are relative to the robot whatever SLAM's
// error. A point is forgotten `keep_s` after it was last seen (people walking leave a trail
// that long), counting only the time it could have been seen again: a door post beside a
// base standing in the doorway is nearer than the Kinects' 0.5 m and out of their view, and
// forgotten after 8 s there it let the base, moving on with a map pose 0.2 m off, onto the
// post (office seed 2, docs/RESULTS.md). Out of view a point is kept up to keep_hidden_s.
#pragma once

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::planning {

struct ObstacleMemoryConfig {
  double cell_m = 0.05;   // m, one remembered point (the newest) per cell of this size.
  double keep_s = 8.0;    // s after a cell was last seen that it is forgotten ...
  // ... of time it was in view; out of view it is kept up to this long after it was last
  // seen. At most keep_s: time out of view counts as in view.
  double keep_hidden_s = 60.0;
  double range_m = 2.5;   // m from the base: farther points are not remembered.
};

class ObstacleMemory {
 public:
  explicit ObstacleMemory(ObstacleMemoryConfig config = {});

  // Points (x, y in base) seen at `stamp_ns` with the base at `T_odom_base`.
  void Insert(const std::vector<Eigen::Vector2d>& points_base, const robotio::Pose2D& T_odom_base,
              std::int64_t stamp_ns);
  // Whether a point (x, y in base) is where the Kinects could see it.
  using InView = std::function<bool(const Eigen::Vector2d& p_base)>;
  // Forgets the cells seen last more than keep_s before `now_ns` (all in view).
  void Forget(std::int64_t now_ns);
  // The same, counting only time in view: a cell `in_view` does not hold for, with the base
  // at `T_odom_base`, is kept (up to keep_hidden_s after it was last seen).
  void Forget(std::int64_t now_ns, const robotio::Pose2D& T_odom_base, const InView& in_view);
  // Remembered points within `radius_m` of the base at `T_odom_base`, as x, y in base.
  [[nodiscard]] std::vector<Eigen::Vector2d> PointsNear(const robotio::Pose2D& T_odom_base,
                                                        double radius_m) const;
  [[nodiscard]] std::size_t size() const { return cells_.size(); }
  [[nodiscard]] const ObstacleMemoryConfig& config() const { return config_; }

 private:
  struct Remembered {
    Eigen::Vector2d p_odom;
    std::int64_t stamp_ns = 0;   // Capture time it was last seen.
    std::int64_t hidden_ns = 0;  // Last time it was out of view (0: never since seen).
  };
  ObstacleMemoryConfig config_;
  std::unordered_map<std::uint64_t, Remembered> cells_;
};

}  // namespace dynamap::planning
