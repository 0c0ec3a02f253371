#include "dynamap/planning/ObstacleMemory.hpp"

#include <algorithm>
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
    if (stamp_ns >= cell.stamp_ns) cell = {q, stamp_ns, 0};
  }
}

void ObstacleMemory::Forget(std::int64_t now_ns) {
  Forget(now_ns, {}, [](const Eigen::Vector2d& /*p_base*/) { return true; });
}

void ObstacleMemory::Forget(std::int64_t now_ns, const robotio::Pose2D& T_odom_base,
                            const InView& in_view) {
  const auto keep_ns = static_cast<std::int64_t>(config_.keep_s * 1e9);
  const auto keep_hidden_ns = static_cast<std::int64_t>(config_.keep_hidden_s * 1e9);
  const double c = std::cos(T_odom_base.theta);
  const double s = std::sin(T_odom_base.theta);
  const double range_squared = config_.range_m * config_.range_m;
  for (auto it = cells_.begin(); it != cells_.end();) {
    Remembered& cell = it->second;
    const Eigen::Vector2d d = cell.p_odom - Eigen::Vector2d(T_odom_base.x, T_odom_base.y);
    // Beyond range_m it ages as if in view: the memory is for what is near the base.
    const Eigen::Vector2d p_base(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
    if (d.squaredNorm() <= range_squared && !in_view(p_base)) cell.hidden_ns = now_ns;
    // In view for keep_s since it was last seen or hidden, or seen too long ago at all.
    const bool unseen_in_view = now_ns - std::max(cell.stamp_ns, cell.hidden_ns) > keep_ns;
    const bool too_old = now_ns - cell.stamp_ns > std::max(keep_ns, keep_hidden_ns);
    it = unseen_in_view || too_old ? cells_.erase(it) : std::next(it);
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
