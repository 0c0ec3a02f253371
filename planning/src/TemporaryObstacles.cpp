#include "dynamap/planning/TemporaryObstacles.hpp"

#include <algorithm>

namespace dynamap::planning {

void TemporaryObstacles::Add(const std::vector<Eigen::Vector2d>& points_base,
                             const robotio::Pose2D& pose, double now_s) {
  for (const Eigen::Vector2d& q : points_base) {
    const robotio::Pose2D p = pose.Compose({q.x(), q.y(), 0.0});
    points_.push_back({{p.x, p.y}, now_s + lifetime_s_});
  }
}

GridMap TemporaryObstacles::Apply(const GridMap& map, double now_s) const {
  GridMap out = map;
  for (const Point& p : points_) {
    if (now_s >= p.until_s) continue;
    const GridIndex c = out.CellAt(p.p_map.x(), p.p_map.y());
    if (out.Contains(c)) out.Set(c, CellState::kObstacle);
  }
  return out;
}

void TemporaryObstacles::Expire(double now_s) {
  points_.erase(std::remove_if(points_.begin(), points_.end(),
                               [now_s](const Point& p) { return now_s >= p.until_s; }),
                points_.end());
}

}  // namespace dynamap::planning
