// The robot's footprint against a world at a given time: the clearance to the nearest
// wall, furniture, door, person, step or hole edge (negative = overlapping).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamap/robotio/sim/World.hpp"
#include "dynamap/robotio/sim/WorldTimeline.hpp"

namespace dynamap::robotio::sim {

struct Contact {
  double clearance_m = 1e9;  // m, footprint edge to the nearest obstacle; < 0 overlaps.
  int object_index = -1;     // Into World::objects; -1 when nothing is near.
};

class CollisionWorld {
 public:
  // robot_height_m: solids starting above it pass over the robot.
  CollisionWorld(const World& world, double robot_height_m);

  // Centre in the world frame; radius of the circular footprint; moving objects at their
  // own schedule times when `clocks` is given (see MovingSolidsAt).
  [[nodiscard]] Contact Check(const Eigen::Vector2d& centre, double radius, double t_s,
                              const ScheduleClocks* clocks = nullptr) const;
  // Clearance between the footprint and one person standing as `state` says.
  [[nodiscard]] double PersonClearance(const Person& person, const PersonState& state,
                                       const Eigen::Vector2d& centre, double radius) const;
  // The same against any solids (a door in its next state, furniture where it goes).
  [[nodiscard]] Contact CheckSolids(const std::vector<Solid>& solids, const Eigen::Vector2d& c,
                                    double radius) const;

 private:
  const World* world_;
  double robot_height_m_;
  std::vector<Solid> fixed_;
};

}  // namespace dynamap::robotio::sim
