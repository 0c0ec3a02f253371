#include "dynamap/planning/MapGuard.hpp"

#include <algorithm>
#include <cmath>

namespace dynamap::planning {

namespace {
constexpr double kMinApproachShare = 0.3;  // Of the distance travelled.
}  // namespace

double DistanceToKnownObstacle(const GridMap& map, double x_m, double y_m, double search_m) {
  const GridIndex c = map.CellAt(x_m, y_m);
  const int r = static_cast<int>(std::ceil(search_m / map.resolution_m)) + 1;
  double best = search_m;
  for (int y = c.y - r; y <= c.y + r; ++y) {
    for (int x = c.x - r; x <= c.x + r; ++x) {
      const GridIndex n{x, y};
      if (!map.Contains(n)) continue;
      const CellState state = map.At(n);
      if (state != CellState::kObstacle && state != CellState::kHole) continue;
      // The surface that made the cell an obstacle lies anywhere in it: its centre is the
      // unbiased estimate (the nearest edge would narrow every doorway by a cell per side).
      best = std::min(best, std::hypot(map.CenterX(x) - x_m, map.CenterY(y) - y_m));
    }
  }
  return best;
}

bool DrivesIntoKnownObstacle(const GridMap& map, const robotio::Pose2D& pose,
                             const robotio::VelocityCommand& command, double footprint_m,
                             double horizon_s) {
  if (std::abs(command.v) < 1e-6) return false;
  // Straight-line prediction over the short horizon (the arc differs by millimetres).
  const double heading = pose.theta + 0.5 * command.omega * horizon_s;
  const double x = pose.x + command.v * horizon_s * std::cos(heading);
  const double y = pose.y + command.v * horizon_s * std::sin(heading);
  const double search = footprint_m + std::abs(command.v) * horizon_s + map.resolution_m;
  const double after = DistanceToKnownObstacle(map, x, y, search);
  if (after >= footprint_m) return false;
  // Heading into the obstacle, not sliding past it: a doorway post abeam comes nearer by a
  // little as the base passes it, a post ahead by most of the distance travelled.
  const double approach = DistanceToKnownObstacle(map, pose.x, pose.y, search) - after;
  return approach > kMinApproachShare * std::abs(command.v) * horizon_s;
}

}  // namespace dynamap::planning
