// A simulated world as a world file describes it: floor, walls, doors, furniture, holes,
// steps, people and the robot's start and scripted motion (DESIGN.md, robotio → Simulator).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::robotio::sim {

enum class ObjectKind { kFloor, kWall, kDoor, kFurniture, kHole, kStep, kPerson };

// One entry per labelled object; label value = index in World::objects + 1.
struct ObjectInfo {
  std::string id;
  ObjectKind kind = ObjectKind::kFloor;
};

struct Wall {
  std::string id;
  int index = 0;                              // Into World::objects.
  Eigen::Vector2d from = Eigen::Vector2d::Zero();  // m, world frame, centre line start.
  Eigen::Vector2d to = Eigen::Vector2d::Zero();    // m, world frame, centre line end.
  double thickness = 0.1;                     // m.
  double height = 2.5;                        // m above the floor.
};

struct DoorEvent {
  double t_s = 0.0;  // s of simulated time when the door changes state.
  bool open = true;  // State from t_s on.
};

// A door panel hinged (or sliding) at `hinge`; closed it spans `width` along closed_yaw.
struct Door {
  std::string id;
  int index = 0;
  Eigen::Vector2d hinge = Eigen::Vector2d::Zero();  // m, world frame, hinge edge on the floor.
  double width = 0.9;            // m, panel width.
  double thickness = 0.04;       // m.
  double height = 2.0;           // m.
  double closed_yaw = 0.0;       // rad, world frame, direction hinge → free edge when closed.
  double open_yaw = M_PI / 2.0;  // rad, same when open (hinged doors).
  bool sliding = false;          // Sliding doors move back along -closed_yaw by `width`.
  bool initially_open = true;    // State at t = 0.
  std::vector<DoorEvent> schedule;  // Sorted by t_s.
};

struct FurnitureMove {
  double t_s = 0.0;  // s, the object is at `pose` from t_s on.
  Pose2D pose;       // World frame, centre of the footprint.
};

enum class FurnitureShape { kBox, kTable, kChair };

struct Furniture {
  std::string id;
  int index = 0;
  FurnitureShape shape = FurnitureShape::kBox;
  Pose2D pose;                                      // World frame, footprint centre, at t = 0.
  Eigen::Vector3d size = Eigen::Vector3d(1, 1, 1);  // m, length (along yaw), width, height.
  std::vector<FurnitureMove> moves;                 // Sorted by t_s.
};

// A hole in the floor (descending stairs): an axis-aligned pit.
struct Hole {
  std::string id;
  int index = 0;
  Eigen::Vector2d min = Eigen::Vector2d::Zero();  // m, world frame.
  Eigen::Vector2d max = Eigen::Vector2d::Zero();  // m, world frame.
  double depth = 3.0;                             // m below the floor.
};

// An ascending step: a block on the floor.
struct Step {
  std::string id;
  int index = 0;
  Pose2D pose;                                   // World frame, footprint centre.
  Eigen::Vector2d size = Eigen::Vector2d(1, 0.3);  // m, along yaw, across.
  double height = 0.17;                          // m.
};

struct Waypoint {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // m, world frame.
  double pause_s = 0.0;                                // s standing here on arrival.
};

struct Person {
  std::string id;
  int index = 0;
  double radius = 0.25;  // m, body cylinder.
  double height = 1.75;  // m.
  double speed = 1.0;    // m/s between waypoints.
  double start_s = 0.0;  // s, stands at the first waypoint until then.
  bool loop = true;      // Back to the first waypoint and again, or stop at the last.
  bool screen = false;   // Carries a 1.5 x 1 m screen at its side, along its heading.
  bool yields = true;    // Waits while its next step would bring it nearer than the
                         // simulator's yield clearance to the robot, backs off the way it
                         // came when the robot comes nearer and gives way when the robot
                         // stays in its way, as people do; false walks its schedule
                         // regardless (into a standing robot).
  std::vector<Waypoint> path;
};

// Scripted teleoperation: constant (v, omega) for duration_s each, then standstill.
struct TeleopSegment {
  double v = 0.0;           // m/s.
  double omega = 0.0;       // rad/s.
  double duration_s = 0.0;  // s.
};

struct World {
  std::string name;
  std::string file;                                   // Where it was loaded from.
  Eigen::Vector2d floor_min = Eigen::Vector2d::Zero();  // m, world frame.
  Eigen::Vector2d floor_max = Eigen::Vector2d::Zero();  // m, world frame.
  Pose2D robot_start;                                 // World frame; defines the map frame.
  double duration_s = 60.0;  // s, the run's end: what stands then is static ground truth.
  std::vector<ObjectInfo> objects;  // Index 0 is the floor.
  std::vector<Wall> walls;
  std::vector<Door> doors;
  std::vector<Furniture> furniture;
  std::vector<Hole> holes;
  std::vector<Step> steps;
  std::vector<Person> people;
  std::vector<TeleopSegment> teleop;

  // World → map (the map's origin and heading are the robot's start pose).
  [[nodiscard]] Eigen::Isometry3d T_map_world() const;
  // Map → world planar pose conversions.
  [[nodiscard]] Pose2D ToMap(const Pose2D& world_pose) const;
  [[nodiscard]] Pose2D ToWorld(const Pose2D& map_pose) const;
  // Index into objects of the object with this id, or -1.
  [[nodiscard]] int FindObject(const std::string& id) const;
};

// The scripted teleop command at time t_s (zero after the script ends).
[[nodiscard]] std::pair<double, double> TeleopCommandAt(const World& world, double t_s);

}  // namespace dynamap::robotio::sim
