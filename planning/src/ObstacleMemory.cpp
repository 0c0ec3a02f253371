#include "dynamap/planning/ObstacleMemory.hpp"

#include <cmath>

namespace dynamap::planning {

namespace {

std::uint64_t CellKey(const Eigen::Vector2d& p, double cell_m) {
  const auto x = static_cast<std::int32_t>(std::floor(p.x() / cell_m));
  const auto y = static_cast<std::int32_t>(std::floor(p.y() / cell_m));
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) |
         static_cast<std::uint32_t>(y);
}

}  // namespace

ObstacleMemory::ObstacleMemory(ObstacleMemoryConfig config) : config_(config) {}

void ObstacleMemory::Insert(const std::vector<Eigen::Vector2d>& points_base,
                            const robotio::Pose2D& T_odom_base, std::int64_t stamp_ns) {
  const double c = std::cos(T_odom_base.theta);
  const double s = std::sin(T_odom_base.theta);
  const double range_squared = config_.range_m * config_.range_m;
  for (const Eigen::Vector2d& p : points_base) {
    if (p.squaredNorm() > range_squared) continue;
    const Eigen::Vector2d q(T_odom_base.x + c * p.x() - s * p.y(),
                            T_odom_base.y + s * p.x() + c * p.y());
    Remembered& cell = cells_[CellKey(q, config_.cell_m)];
    if (stamp_ns >= cell.stamp_ns) cell = {q, stamp_ns};
  }
}

void ObstacleMemory::Forget(std::int64_t now_ns) {
  const auto keep_ns = static_cast<std::int64_t>(config_.keep_s * 1e9);
  for (auto it = cells_.begin(); it != cells_.end();) {
    it = now_ns - it->second.stamp_ns > keep_ns ? cells_.erase(it) : std::next(it);
  }
}

std::vector<Eigen::Vector2d> ObstacleMemory::PointsNear(const robotio::Pose2D& T_odom_base,
                                                        double radius_m) const {
  std::vector<Eigen::Vector2d> points;
  const double c = std::cos(T_odom_base.theta);
  const double s = std::sin(T_odom_base.theta);
  const double radius_squared = radius_m * radius_m;
  for (const auto& [key, cell] : cells_) {
    const Eigen::Vector2d d = cell.p_odom - Eigen::Vector2d(T_odom_base.x, T_odom_base.y);
    if (d.squaredNorm() > radius_squared) continue;
    points.emplace_back(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
  }
  return points;
}

}  // namespace dynamap::planning
