#include "dynamap/robotio/sim/WorldTimeline.hpp"

#include <algorithm>
#include <cmath>

namespace dynamap::robotio::sim {

namespace {

constexpr double kScreenLength = 1.5;     // m, along the carrier's heading.
constexpr double kScreenHeight = 1.0;     // m.
constexpr double kScreenThickness = 0.03;  // m.
constexpr double kScreenBottom = 0.4;     // m above the floor.

// A box given in `frame`'s local coordinates (centre offset dx, dy).
Solid LocalBox(const Pose2D& frame, double dx, double dy, double z0, double lx, double ly,
               double lz, int index) {
  Solid s;
  s.type = Solid::Type::kBox;
  s.pose = frame.Compose({dx, dy, 0.0});
  s.size = {lx, ly, lz};
  s.z0 = z0;
  s.object_index = index;
  return s;
}

bool SamePose(const Pose2D& a, const Pose2D& b) {
  return std::abs(a.x - b.x) < 1e-9 && std::abs(a.y - b.y) < 1e-9 &&
         std::abs(WrapAngle(a.theta - b.theta)) < 1e-9;
}

}  // namespace

bool DoorOpenAt(const Door& door, double t_s) {
  bool open = door.initially_open;
  for (const DoorEvent& e : door.schedule) {
    if (t_s >= e.t_s) open = e.open;
  }
  return open;
}

Pose2D FurniturePoseAt(const Furniture& furniture, double t_s) {
  Pose2D pose = furniture.pose;
  for (const FurnitureMove& m : furniture.moves) {
    if (t_s >= m.t_s) pose = m.pose;
  }
  return pose;
}

PersonState PersonAt(const Person& person, double t_s) {
  const auto& path = person.path;
  const std::size_t n = path.size();
  auto heading_to = [&](std::size_t i) {
    const std::size_t j = person.loop ? (i + 1) % n : std::min(i + 1, n - 1);
    const Eigen::Vector2d d = path[j].position - path[i].position;
    if (d.norm() < 1e-9 && i > 0) {
      const Eigen::Vector2d back = path[i].position - path[i - 1].position;
      return std::atan2(back.y(), back.x());
    }
    return std::atan2(d.y(), d.x());
  };
  if (n == 1 || t_s <= person.start_s) return {path[0].position, heading_to(0)};
  // Legs: pause at waypoint i, then walk to the next one.
  const std::size_t legs = person.loop ? n : n - 1;
  double cycle = 0.0;
  for (std::size_t i = 0; i < legs; ++i) {
    cycle += path[i].pause_s + (path[(i + 1) % n].position - path[i].position).norm() / person.speed;
  }
  double tau = t_s - person.start_s;
  if (person.loop && cycle > 0.0) tau = std::fmod(tau, cycle);
  for (std::size_t i = 0; i < legs; ++i) {
    if (tau < path[i].pause_s) return {path[i].position, heading_to(i)};
    tau -= path[i].pause_s;
    const Eigen::Vector2d from = path[i].position;
    const Eigen::Vector2d to = path[(i + 1) % n].position;
    const double walk = (to - from).norm() / person.speed;
    if (tau < walk) {
      return {from + (to - from) * (tau / walk), std::atan2(to.y() - from.y(), to.x() - from.x())};
    }
    tau -= walk;
  }
  return {path[legs % n].position, heading_to(legs == n ? 0 : n - 1)};
}

std::vector<Solid> DoorSolids(const Door& door, bool open) {
  Pose2D frame{door.hinge.x(), door.hinge.y(), door.closed_yaw};
  if (open && door.sliding) {
    frame = frame.Compose({-door.width, 0.0, 0.0});
  } else if (open) {
    frame.theta = door.open_yaw;
  }
  // Panel from the hinge along the frame's x, a small gap above the floor.
  return {LocalBox(frame, door.width / 2.0, 0.0, 0.01, door.width, door.thickness,
                   door.height - 0.01, door.index)};
}

std::vector<Solid> FurnitureSolids(const Furniture& f, const Pose2D& pose) {
  const double lx = f.size.x();
  const double ly = f.size.y();
  const double lz = f.size.z();
  std::vector<Solid> solids;
  auto legs = [&](double leg, double height) {
    const double ox = lx / 2.0 - leg;
    const double oy = ly / 2.0 - leg;
    for (const double sx : {-1.0, 1.0}) {
      for (const double sy : {-1.0, 1.0}) {
        solids.push_back(LocalBox(pose, sx * ox, sy * oy, 0.0, leg, leg, height, f.index));
      }
    }
  };
  switch (f.shape) {
    case FurnitureShape::kBox:
      solids.push_back(LocalBox(pose, 0.0, 0.0, 0.0, lx, ly, lz, f.index));
      break;
    case FurnitureShape::kTable: {
      const double top = std::min(0.04, lz * 0.2);
      solids.push_back(LocalBox(pose, 0.0, 0.0, lz - top, lx, ly, top, f.index));
      legs(0.05, lz - top);
      break;
    }
    case FurnitureShape::kChair: {
      // Seat at 45% of the height (at most 0.46 m), back rest on the -x edge.
      const double seat = std::min(0.46, lz * 0.45);
      solids.push_back(LocalBox(pose, 0.0, 0.0, seat - 0.04, lx, ly, 0.04, f.index));
      legs(0.03, seat - 0.04);
      solids.push_back(LocalBox(pose, -lx / 2.0 + 0.02, 0.0, seat, 0.04, ly, lz - seat, f.index));
      break;
    }
  }
  return solids;
}

std::vector<Solid> PersonSolids(const Person& person, const PersonState& state) {
  std::vector<Solid> solids;
  Solid body;
  body.type = Solid::Type::kCylinder;
  body.pose = {state.position.x(), state.position.y(), state.heading};
  body.size = {person.radius, person.radius, person.height};
  body.object_index = person.index;
  body.dynamic = true;
  solids.push_back(body);
  if (person.screen) {
    Solid screen = LocalBox(body.pose, 0.0, person.radius + 0.1, kScreenBottom, kScreenLength,
                            kScreenThickness, kScreenHeight, person.index);
    screen.dynamic = true;
    solids.push_back(screen);
  }
  return solids;
}

namespace {

double SegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                       const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length2 = ab.squaredNorm();
  const double t = length2 > 0.0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// Whether the end `p` of wall `self` meets another wall (a corner or a T-junction).
bool MeetsAnotherWall(const World& world, std::size_t self, const Eigen::Vector2d& p) {
  for (std::size_t i = 0; i < world.walls.size(); ++i) {
    if (i == self) continue;
    const Wall& o = world.walls[i];
    if (SegmentDistance(p, o.from, o.to) <= (o.thickness + world.walls[self].thickness) / 2.0) {
      return true;
    }
  }
  return false;
}

}  // namespace

Solid WallSolid(const World& world, std::size_t i) {
  const Wall& w = world.walls.at(i);
  const Eigen::Vector2d d = w.to - w.from;
  const Eigen::Vector2d along =
      d.norm() > 0.0 ? Eigen::Vector2d(d.normalized()) : Eigen::Vector2d::UnitX();
  const double back = MeetsAnotherWall(world, i, w.from) ? w.thickness / 2.0 : 0.0;
  const double ahead = MeetsAnotherWall(world, i, w.to) ? w.thickness / 2.0 : 0.0;
  const Eigen::Vector2d mid = (w.from + w.to) / 2.0 + along * (ahead - back) / 2.0;
  return LocalBox({mid.x(), mid.y(), std::atan2(along.y(), along.x())}, 0.0, 0.0, 0.0,
                  d.norm() + back + ahead, w.thickness, w.height, w.index);
}

std::vector<Solid> FixedSolids(const World& world) {
  std::vector<Solid> solids;
  for (std::size_t i = 0; i < world.walls.size(); ++i) solids.push_back(WallSolid(world, i));
  for (const Step& s : world.steps) {
    solids.push_back(LocalBox(s.pose, 0.0, 0.0, 0.0, s.size.x(), s.size.y(), s.height, s.index));
  }
  for (const Furniture& f : world.furniture) {
    if (!f.moves.empty()) continue;
    for (const Solid& s : FurnitureSolids(f, f.pose)) solids.push_back(s);
  }
  return solids;
}

std::vector<Solid> MovingSolidsAt(const World& world, double t_s, const ScheduleClocks* clocks) {
  const auto clock = [&](const std::vector<double> ScheduleClocks::*member, std::size_t i) {
    return clocks != nullptr && i < (clocks->*member).size() ? (clocks->*member)[i] : t_s;
  };
  std::vector<Solid> solids;
  for (std::size_t i = 0; i < world.doors.size(); ++i) {
    const Door& d = world.doors[i];
    const bool open = DoorOpenAt(d, clock(&ScheduleClocks::doors_s, i));
    const bool dynamic = open != DoorOpenAt(d, world.duration_s);
    for (Solid s : DoorSolids(d, open)) {
      s.dynamic = dynamic;
      solids.push_back(s);
    }
  }
  for (std::size_t i = 0; i < world.furniture.size(); ++i) {
    const Furniture& f = world.furniture[i];
    if (f.moves.empty()) continue;
    const Pose2D pose = FurniturePoseAt(f, clock(&ScheduleClocks::furniture_s, i));
    const bool dynamic = !SamePose(pose, FurniturePoseAt(f, world.duration_s));
    for (Solid s : FurnitureSolids(f, pose)) {
      s.dynamic = dynamic;
      solids.push_back(s);
    }
  }
  for (std::size_t i = 0; i < world.people.size(); ++i) {
    const double t = clock(&ScheduleClocks::people_s, i);
    for (const Solid& s : PersonSolids(world.people[i], PersonAt(world.people[i], t))) {
      solids.push_back(s);
    }
  }
  return solids;
}

std::vector<Solid> FinalMovableSolids(const World& world) {
  std::vector<Solid> solids;
  for (const Door& d : world.doors) {
    for (const Solid& s : DoorSolids(d, DoorOpenAt(d, world.duration_s))) solids.push_back(s);
  }
  for (const Furniture& f : world.furniture) {
    if (f.moves.empty()) continue;
    for (const Solid& s : FurnitureSolids(f, FurniturePoseAt(f, world.duration_s))) {
      solids.push_back(s);
    }
  }
  return solids;
}

}  // namespace dynamap::robotio::sim
