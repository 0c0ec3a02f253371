#include "dynamap/robotio/sim/CollisionWorld.hpp"

#include <cmath>

namespace dynamap::robotio::sim {

namespace {

// Signed distance from a point to an axis-aligned box of half extents `half` at the origin.
double BoxDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& half) {
  const Eigen::Vector2d q = p.cwiseAbs() - half;
  return q.cwiseMax(0.0).norm() + std::min(std::max(q.x(), q.y()), 0.0);
}

double SolidDistance(const Solid& s, const Eigen::Vector2d& c) {
  const Eigen::Vector2d d = c - Eigen::Vector2d(s.pose.x, s.pose.y);
  if (s.type == Solid::Type::kCylinder) return d.norm() - s.size.x();
  const double cs = std::cos(s.pose.theta);
  const double sn = std::sin(s.pose.theta);
  const Eigen::Vector2d local(cs * d.x() + sn * d.y(), -sn * d.x() + cs * d.y());
  return BoxDistance(local, s.size.head<2>() / 2.0);
}

}  // namespace

CollisionWorld::CollisionWorld(const World& world, double robot_height_m)
    : world_(&world), robot_height_m_(robot_height_m), fixed_(FixedSolids(world)) {}

Contact CollisionWorld::CheckSolids(const std::vector<Solid>& solids, const Eigen::Vector2d& c,
                                    double radius) const {
  Contact best;
  for (const Solid& s : solids) {
    if (s.z0 >= robot_height_m_) continue;
    const double clearance = SolidDistance(s, c) - radius;
    if (clearance < best.clearance_m) best = {clearance, s.object_index};
  }
  return best;
}

Contact CollisionWorld::Check(const Eigen::Vector2d& centre, double radius, double t_s,
                              const ScheduleClocks* clocks) const {
  Contact best = CheckSolids(fixed_, centre, radius);
  const Contact moving =
      CheckSolids(MovingSolidsAt(*world_, t_s, clocks), centre, radius);
  if (moving.clearance_m < best.clearance_m) best = moving;
  for (const Hole& h : world_->holes) {
    const Eigen::Vector2d mid = (h.min + h.max) / 2.0;
    const double clearance = BoxDistance(centre - mid, (h.max - h.min) / 2.0) - radius;
    if (clearance < best.clearance_m) best = {clearance, h.index};
  }
  return best;
}

double CollisionWorld::PersonClearance(const Person& person, const PersonState& state,
                                       const Eigen::Vector2d& centre, double radius) const {
  return CheckSolids(PersonSolids(person, state), centre, radius).clearance_m;
}

}  // namespace dynamap::robotio::sim
