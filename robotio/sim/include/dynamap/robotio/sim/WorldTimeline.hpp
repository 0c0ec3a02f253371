// Where every object of a world is at a given time (door states, furniture moves, people
// on their paths) as simple solids, and which of them are dynamic ground truth: people
// always, movable objects in every placement other than the one they end the run in.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::robotio::sim {

// An upright box (yawed about z) or a vertical cylinder standing on z0.
struct Solid {
  enum class Type { kBox, kCylinder };
  Type type = Type::kBox;
  Pose2D pose;  // World frame: box footprint centre and yaw, or cylinder axis.
  Eigen::Vector3d size = Eigen::Vector3d::Ones();  // m: box length (along yaw), width,
                                                    // height; cylinder radius, -, height.
  double z0 = 0.0;         // m, bottom above the floor.
  int object_index = 0;    // Into World::objects.
  bool dynamic = false;    // Must not end in the static map (ground-truth label).
};

struct PersonState {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // m, world frame.
  double heading = 0.0;                                // rad, world frame.
};

[[nodiscard]] bool DoorOpenAt(const Door& door, double t_s);
[[nodiscard]] Pose2D FurniturePoseAt(const Furniture& furniture, double t_s);
[[nodiscard]] PersonState PersonAt(const Person& person, double t_s);

[[nodiscard]] std::vector<Solid> DoorSolids(const Door& door, bool open);
[[nodiscard]] std::vector<Solid> FurnitureSolids(const Furniture& furniture, const Pose2D& pose);
[[nodiscard]] std::vector<Solid> PersonSolids(const Person& person, const PersonState& state);

// Wall i as a box. Walls overlap by half their thickness where they meet another wall, so
// corners have no gaps; a free end (a doorway's side) stops at its point, so a doorway is
// as wide as the world file says.
[[nodiscard]] Solid WallSolid(const World& world, std::size_t i);
// Walls, steps and furniture that never moves: the same for the whole run.
[[nodiscard]] std::vector<Solid> FixedSolids(const World& world);
// Each moving object's own schedule time, behind the mission clock by the time it waited
// for the robot: a person that would walk into it, a door that would close or open onto
// it, a piece of furniture that would be put where it stands. Indexed like World::people,
// World::doors and World::furniture; an object without an entry is at the mission time.
struct ScheduleClocks {
  std::vector<double> people_s;
  std::vector<double> doors_s;
  std::vector<double> furniture_s;
};

// Doors, furniture with moves and people at time t_s, labelled against world.duration_s;
// each at its own schedule time when `clocks` is given.
[[nodiscard]] std::vector<Solid> MovingSolidsAt(const World& world, double t_s,
                                                const ScheduleClocks* clocks = nullptr);
// Doors and movable furniture in the placement they end the run in (static map truth).
[[nodiscard]] std::vector<Solid> FinalMovableSolids(const World& world);

}  // namespace dynamap::robotio::sim
