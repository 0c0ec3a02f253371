// Obstacles the collision guard reported, kept on the projected map for a while so the
// path is replanned around them even before (or without) the 3D map showing them
// (thesis 7.1.2, collision handling).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::planning {

class TemporaryObstacles {
 public:
  explicit TemporaryObstacles(double lifetime_s = 10.0) : lifetime_s_(lifetime_s) {}

  // Points in base (the guard's verdict) seen at base pose `pose` (map frame) at `now_s`.
  void Add(const std::vector<Eigen::Vector2d>& points_base, const robotio::Pose2D& pose,
           double now_s);
  // `map` with the unexpired obstacles marked (cells outside it are ignored).
  [[nodiscard]] GridMap Apply(const GridMap& map, double now_s) const;
  void Expire(double now_s);
  [[nodiscard]] std::size_t size() const { return points_.size(); }

 private:
  struct Point {
    Eigen::Vector2d p_map;
    double until_s;
  };
  double lifetime_s_;
  std::vector<Point> points_;
};

}  // namespace dynamap::planning
