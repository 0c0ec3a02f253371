#include "dynamap/robotio/sim/WorldLoader.hpp"

#include <cmath>
#include <set>

#include "dynamap/robotio/ConfigReader.hpp"

namespace dynamap::robotio::sim {

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kMaxCoord = 1000.0;  // m, any coordinate in a world file.

Eigen::Vector2d ReadPoint(ConfigNode& node, const std::string& key) {
  return node.RequireVector(key, 2, -kMaxCoord, kMaxCoord);
}

// "[x, y, yaw_deg]".
Pose2D ReadPose(ConfigNode& node, const std::string& key) {
  const Eigen::VectorXd v = node.RequireVector(key, 3, -kMaxCoord, kMaxCoord);
  return {v[0], v[1], WrapAngle(v[2] * kDeg)};
}

// The "teleop:" list of `node`: (v, omega) held for duration_s each.
std::vector<TeleopSegment> ParseTeleopList(ConfigNode& node) {
  std::vector<TeleopSegment> segments;
  for (ConfigNode& n : node.ChildList("teleop")) {
    TeleopSegment s;
    s.v = n.RequireDouble("v", -2.0, 2.0);
    s.omega = n.RequireDouble("omega", -5.0, 5.0);
    s.duration_s = n.RequireDouble("duration_s", 0.0, 1e5);
    segments.push_back(s);
  }
  return segments;
}

class Parser {
 public:
  explicit Parser(ConfigNode& root) : root_(root) {}

  World Parse() {
    world_.objects.push_back({"floor", ObjectKind::kFloor});
    ids_.insert("floor");
    world_.file = root_.file();
    root_.Read("name", &world_.name);
    root_.Read("duration_s", &world_.duration_s, 0.1, 1e5);
    ConfigNode floor = root_.Child("floor");
    world_.floor_min = ReadPoint(floor, "min");
    world_.floor_max = ReadPoint(floor, "max");
    if ((world_.floor_max - world_.floor_min).minCoeff() <= 0.0) {
      floor.Fail("max", "must be greater than floor.min in x and y");
    }
    ConfigNode start = root_.Child("robot_start");
    const double yaw_deg = start.RequireDouble("yaw_deg", -360.0, 360.0);
    world_.robot_start = {start.RequireDouble("x", -kMaxCoord, kMaxCoord),
                          start.RequireDouble("y", -kMaxCoord, kMaxCoord),
                          WrapAngle(yaw_deg * kDeg)};
    CheckOnFloor(start, "x", {world_.robot_start.x, world_.robot_start.y});
    if (root_.Has("walls")) {
      for (ConfigNode& n : root_.ChildList("walls")) ParseWall(n);
    }
    if (root_.Has("doors")) {
      for (ConfigNode& n : root_.ChildList("doors")) ParseDoor(n);
    }
    if (root_.Has("furniture")) {
      for (ConfigNode& n : root_.ChildList("furniture")) ParseFurniture(n);
    }
    if (root_.Has("holes")) {
      for (ConfigNode& n : root_.ChildList("holes")) ParseHole(n);
    }
    if (root_.Has("steps")) {
      for (ConfigNode& n : root_.ChildList("steps")) ParseStep(n);
    }
    if (root_.Has("people")) {
      for (ConfigNode& n : root_.ChildList("people")) ParsePerson(n);
    }
    if (root_.Has("teleop")) world_.teleop = ParseTeleopList(root_);
    if (world_.objects.size() > 0x7fff) root_.Fail("walls", "too many objects (at most 32767)");
    return world_;
  }

 private:
  int AddObject(ConfigNode& node, ObjectKind kind) {
    const std::string id = node.RequireString("id");
    if (id.empty()) node.Fail("id", "must not be empty");
    if (!ids_.insert(id).second) node.Fail("id", "'" + id + "' is used by two objects");
    world_.objects.push_back({id, kind});
    return static_cast<int>(world_.objects.size()) - 1;
  }

  void CheckOnFloor(ConfigNode& node, const std::string& key, const Eigen::Vector2d& p) const {
    if ((p - world_.floor_min).minCoeff() < 0.0 || (world_.floor_max - p).minCoeff() < 0.0) {
      node.Fail(key, "lies outside the floor (floor.min .. floor.max)");
    }
  }

  void ParseWall(ConfigNode& n) {
    Wall w;
    w.index = AddObject(n, ObjectKind::kWall);
    w.id = world_.objects[w.index].id;
    w.from = ReadPoint(n, "from");
    w.to = ReadPoint(n, "to");
    if ((w.to - w.from).norm() < 1e-3) n.Fail("to", "must differ from 'from' (zero-length wall)");
    n.Read("thickness", &w.thickness, 0.01, 2.0);
    n.Read("height", &w.height, 0.05, 10.0);
    world_.walls.push_back(w);
  }

  void ParseDoor(ConfigNode& n) {
    Door d;
    d.index = AddObject(n, ObjectKind::kDoor);
    d.id = world_.objects[d.index].id;
    d.hinge = ReadPoint(n, "hinge");
    n.Read("width", &d.width, 0.2, 5.0);
    n.Read("thickness", &d.thickness, 0.01, 0.5);
    n.Read("height", &d.height, 0.5, 5.0);
    d.closed_yaw = n.RequireDouble("closed_yaw_deg", -360.0, 360.0) * kDeg;
    std::string type = "hinge";
    n.ReadChoice("type", &type, {"hinge", "slide"});
    d.sliding = type == "slide";
    double open_yaw_deg = d.closed_yaw / kDeg + 90.0;
    n.Read("open_yaw_deg", &open_yaw_deg, -360.0, 360.0);
    d.open_yaw = open_yaw_deg * kDeg;
    n.Read("open", &d.initially_open);
    if (n.Has("schedule")) {
      double last = -1.0;
      for (ConfigNode& e : n.ChildList("schedule")) {
        DoorEvent event;
        event.t_s = e.RequireDouble("t", 0.0, 1e5);
        event.open = [&] {
          bool open = true;
          if (!e.Has("open")) e.Fail("open", "is required (true or false)");
          e.Read("open", &open);
          return open;
        }();
        if (event.t_s <= last) e.Fail("t", "must be later than the previous schedule entry");
        last = event.t_s;
        d.schedule.push_back(event);
      }
    }
    world_.doors.push_back(d);
  }

  void ParseFurniture(ConfigNode& n) {
    Furniture f;
    f.index = AddObject(n, ObjectKind::kFurniture);
    f.id = world_.objects[f.index].id;
    std::string shape = "box";
    n.ReadChoice("shape", &shape, {"box", "table", "chair"});
    f.shape = shape == "table" ? FurnitureShape::kTable
              : shape == "chair" ? FurnitureShape::kChair
                                 : FurnitureShape::kBox;
    f.pose = ReadPose(n, "pose");
    CheckOnFloor(n, "pose", {f.pose.x, f.pose.y});
    f.size = n.RequireVector("size", 3, 0.02, 20.0);
    if (n.Has("moves")) {
      double last = -1.0;
      for (ConfigNode& m : n.ChildList("moves")) {
        FurnitureMove move;
        move.t_s = m.RequireDouble("t", 0.0, 1e5);
        move.pose = ReadPose(m, "pose");
        CheckOnFloor(m, "pose", {move.pose.x, move.pose.y});
        if (move.t_s <= last) m.Fail("t", "must be later than the previous move");
        last = move.t_s;
        f.moves.push_back(move);
      }
    }
    world_.furniture.push_back(f);
  }

  void ParseHole(ConfigNode& n) {
    Hole h;
    h.index = AddObject(n, ObjectKind::kHole);
    h.id = world_.objects[h.index].id;
    h.min = ReadPoint(n, "min");
    h.max = ReadPoint(n, "max");
    if ((h.max - h.min).minCoeff() <= 0.0) n.Fail("max", "must be greater than min in x and y");
    CheckOnFloor(n, "min", h.min);
    CheckOnFloor(n, "max", h.max);
    n.Read("depth", &h.depth, 0.05, 20.0);
    world_.holes.push_back(h);
  }

  void ParseStep(ConfigNode& n) {
    Step s;
    s.index = AddObject(n, ObjectKind::kStep);
    s.id = world_.objects[s.index].id;
    s.pose = ReadPose(n, "pose");
    CheckOnFloor(n, "pose", {s.pose.x, s.pose.y});
    s.size = n.RequireVector("size", 2, 0.02, 50.0);
    n.Read("height", &s.height, 0.005, 2.0);
    world_.steps.push_back(s);
  }

  void ParsePerson(ConfigNode& n) {
    Person p;
    p.index = AddObject(n, ObjectKind::kPerson);
    p.id = world_.objects[p.index].id;
    n.Read("radius", &p.radius, 0.05, 1.0);
    n.Read("height", &p.height, 0.3, 2.5);
    n.Read("speed", &p.speed, 0.01, 5.0);
    n.Read("start_s", &p.start_s, 0.0, 1e5);
    n.Read("loop", &p.loop);
    n.Read("screen", &p.screen);
    n.Read("yields", &p.yields);
    for (ConfigNode& w : n.ChildList("path")) {
      Waypoint waypoint;
      waypoint.position = ReadPoint(w, "at");
      CheckOnFloor(w, "at", waypoint.position);
      w.Read("pause_s", &waypoint.pause_s, 0.0, 1e5);
      p.path.push_back(waypoint);
    }
    if (p.path.empty()) n.Fail("path", "must list at least one waypoint");
    world_.people.push_back(p);
  }

  ConfigNode& root_;
  World world_;
  std::set<std::string> ids_;
};

World ParseRoot(ConfigNode& root) { return Parser(root).Parse(); }

}  // namespace

Expected<World> LoadWorld(const std::string& file) {
  return ParseYamlFile<World>(file, ParseRoot);
}

Expected<std::vector<TeleopSegment>> LoadTeleop(const std::string& file) {
  return ParseYamlFile<std::vector<TeleopSegment>>(file, [](ConfigNode& root) {
    std::string name, description;
    root.Read("name", &name);
    root.Read("description", &description);
    std::vector<TeleopSegment> segments = ParseTeleopList(root);
    if (segments.empty()) root.Fail("teleop", "must list at least one segment");
    return segments;
  });
}

Expected<World> ParseWorld(const std::string& yaml_text, const std::string& name) {
  return ParseYamlText<World>(yaml_text, name, ParseRoot);
}

}  // namespace dynamap::robotio::sim
