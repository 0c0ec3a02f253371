#include "dynamap/robotio/sim/WorldRender.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dynamap/robotio/sim/WorldTimeline.hpp"

namespace dynamap::robotio::sim {

namespace {

const cv::Scalar kOutside(200, 200, 200);
const cv::Scalar kFloor(250, 250, 248);
const cv::Scalar kGrid(232, 232, 228);
const cv::Scalar kWall(40, 40, 40);
const cv::Scalar kDoor(30, 120, 230);  // BGR: orange.
const cv::Scalar kFurniture(60, 110, 170);
const cv::Scalar kFurnitureFill(170, 205, 230);
const cv::Scalar kHole(70, 30, 30);
const cv::Scalar kStep(60, 170, 230);
const cv::Scalar kRobot(40, 160, 40);
const cv::Scalar kText(30, 30, 30);
const cv::Scalar kPeople[] = {{40, 40, 220}, {180, 40, 180}, {30, 140, 230}, {150, 90, 0},
                              {90, 30, 140}, {0, 120, 120}};

class Canvas {
 public:
  Canvas(const World& world, const WorldRenderConfig& config) : world_(world), config_(config) {
    const Eigen::Vector2d extent = world.floor_max - world.floor_min;
    // Room below the floor for the scale bar and two legend lines; wide enough for them.
    image_ = cv::Mat(static_cast<int>(extent.y() * config.pixels_per_metre) + 2 * config.margin_px + 40,
                     std::max(820, static_cast<int>(extent.x() * config.pixels_per_metre) +
                                       2 * config.margin_px),
                     CV_8UC3, kOutside);
  }

  cv::Point Px(double x, double y) const {
    return {static_cast<int>(std::lround((x - world_.floor_min.x()) * config_.pixels_per_metre)) +
                config_.margin_px,
            static_cast<int>(std::lround((world_.floor_max.y() - y) * config_.pixels_per_metre)) +
                config_.margin_px};
  }
  cv::Point Px(const Eigen::Vector2d& p) const { return Px(p.x(), p.y()); }
  int Len(double metres) const { return static_cast<int>(std::lround(metres * config_.pixels_per_metre)); }

  std::vector<cv::Point> Footprint(const Solid& s) const {
    std::vector<cv::Point> points;
    if (s.type == Solid::Type::kCylinder) return points;
    const double c = std::cos(s.pose.theta);
    const double sn = std::sin(s.pose.theta);
    const double hx = s.size.x() / 2.0;
    const double hy = s.size.y() / 2.0;
    for (const auto& [lx, ly] : {std::pair{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}}) {
      points.push_back(Px(s.pose.x + c * lx - sn * ly, s.pose.y + sn * lx + c * ly));
    }
    return points;
  }

  void FillSolid(const Solid& s, const cv::Scalar& fill, const cv::Scalar& edge) {
    const auto points = Footprint(s);
    if (points.empty()) return;
    cv::fillConvexPoly(image_, points, fill, cv::LINE_AA);
    cv::polylines(image_, points, true, edge, 1, cv::LINE_AA);
  }

  void DashedLine(const cv::Point& a, const cv::Point& b, const cv::Scalar& color, int thickness) {
    const double length = cv::norm(b - a);
    const int dashes = std::max(1, static_cast<int>(length / 8.0));
    for (int i = 0; i < dashes; i += 2) {
      const cv::Point p = a + (b - a) * (static_cast<double>(i) / dashes);
      const cv::Point q = a + (b - a) * (std::min(1.0, static_cast<double>(i + 1) / dashes));
      cv::line(image_, p, q, color, thickness, cv::LINE_AA);
    }
  }

  void Text(const std::string& text, const cv::Point& at, double scale, const cv::Scalar& color) {
    cv::putText(image_, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, color, 1, cv::LINE_AA);
  }

  cv::Mat& image() { return image_; }

 private:
  const World& world_;
  WorldRenderConfig config_;
  cv::Mat image_;
};

void DrawFloor(const World& world, Canvas& canvas) {
  cv::rectangle(canvas.image(), canvas.Px(world.floor_min.x(), world.floor_max.y()),
                canvas.Px(world.floor_max.x(), world.floor_min.y()), kFloor, cv::FILLED);
  for (double x = std::ceil(world.floor_min.x()); x <= world.floor_max.x(); x += 1.0) {
    cv::line(canvas.image(), canvas.Px(x, world.floor_min.y()), canvas.Px(x, world.floor_max.y()),
             kGrid, 1);
  }
  for (double y = std::ceil(world.floor_min.y()); y <= world.floor_max.y(); y += 1.0) {
    cv::line(canvas.image(), canvas.Px(world.floor_min.x(), y), canvas.Px(world.floor_max.x(), y),
             kGrid, 1);
  }
  for (const Hole& h : world.holes) {
    const cv::Point a = canvas.Px(h.min.x(), h.max.y());
    const cv::Point b = canvas.Px(h.max.x(), h.min.y());
    cv::rectangle(canvas.image(), a, b, kHole, cv::FILLED);
    // Hatching marks "no floor here".
    for (int d = 0; d < (b.x - a.x) + (b.y - a.y); d += 8) {
      cv::Point p(a.x + d, a.y);
      cv::Point q(a.x, a.y + d);
      cv::clipLine(cv::Rect(a, b), p, q);
      cv::line(canvas.image(), p, q, cv::Scalar(140, 110, 110), 1, cv::LINE_AA);
    }
    canvas.Text(h.id, {a.x + 2, b.y - 4}, 0.35, cv::Scalar(255, 255, 255));
  }
}

void DrawObjects(const World& world, Canvas& canvas) {
  for (const Step& s : world.steps) {
    Solid solid;
    solid.pose = s.pose;
    solid.size = {s.size.x(), s.size.y(), s.height};
    canvas.FillSolid(solid, kStep, kFurniture);
  }
  for (const Furniture& f : world.furniture) {
    std::vector<Pose2D> placements{f.pose};
    for (const FurnitureMove& m : f.moves) placements.push_back(m.pose);
    for (std::size_t i = 0; i < placements.size(); ++i) {
      const bool final_place = i + 1 == placements.size();
      Solid outline;
      outline.pose = placements[i];
      outline.size = f.size;
      canvas.FillSolid(outline, final_place ? kFurnitureFill : cv::Scalar(225, 225, 240), kFurniture);
      if (f.shape == FurnitureShape::kChair) {
        // The back rest shows which way the chair faces.
        for (const Solid& s : FurnitureSolids(f, placements[i])) {
          if (s.size.z() > f.size.z() * 0.4 && s.size.x() < 0.1) canvas.FillSolid(s, kFurniture, kFurniture);
        }
      }
      if (i > 0) {
        canvas.DashedLine(canvas.Px(placements[i - 1].x, placements[i - 1].y),
                          canvas.Px(placements[i].x, placements[i].y), kFurniture, 1);
      }
    }
  }
  for (std::size_t i = 0; i < world.walls.size(); ++i) {
    canvas.FillSolid(WallSolid(world, i), kWall, kWall);
  }
  for (const Door& d : world.doors) {
    for (const bool open : {false, true}) {
      for (const Solid& s : DoorSolids(d, open)) {
        canvas.FillSolid(s, open == DoorOpenAt(d, 0.0) ? kDoor : cv::Scalar(170, 210, 250), kDoor);
      }
    }
    if (!d.sliding) {
      double a0 = -d.closed_yaw * 180.0 / M_PI;
      double a1 = -d.open_yaw * 180.0 / M_PI;
      cv::ellipse(canvas.image(), canvas.Px(d.hinge), cv::Size(canvas.Len(d.width), canvas.Len(d.width)),
                  0.0, a0, a1, kDoor, 1, cv::LINE_AA);
    }
  }
}

void DrawPeople(const World& world, Canvas& canvas) {
  for (std::size_t i = 0; i < world.people.size(); ++i) {
    const Person& p = world.people[i];
    const cv::Scalar color = kPeople[i % (sizeof(kPeople) / sizeof(kPeople[0]))];
    for (std::size_t k = 0; k + 1 < p.path.size(); ++k) {
      cv::arrowedLine(canvas.image(), canvas.Px(p.path[k].position), canvas.Px(p.path[k + 1].position),
                      color, 2, cv::LINE_AA, 0, 0.03);
    }
    if (p.loop && p.path.size() > 2) {
      canvas.DashedLine(canvas.Px(p.path.back().position), canvas.Px(p.path.front().position), color, 2);
    }
    for (const Waypoint& w : p.path) {
      if (w.pause_s > 0.0) cv::circle(canvas.image(), canvas.Px(w.position), 4, color, cv::FILLED, cv::LINE_AA);
    }
    const PersonState start = PersonAt(p, 0.0);
    for (const Solid& s : PersonSolids(p, start)) {
      if (s.type == Solid::Type::kCylinder) {
        cv::circle(canvas.image(), canvas.Px(start.position), canvas.Len(p.radius), color, cv::FILLED, cv::LINE_AA);
      } else {
        canvas.FillSolid(s, color, color);
      }
    }
    canvas.Text(p.id, canvas.Px(start.position) + cv::Point(canvas.Len(p.radius) + 3, -3), 0.4, color);
  }
}

void DrawRobot(const World& world, Canvas& canvas) {
  // The scripted teleop path under ideal kinematics.
  Pose2D pose = world.robot_start;
  const double dt = 0.05;
  for (const TeleopSegment& seg : world.teleop) {
    for (double t = 0.0; t < seg.duration_s; t += dt) {
      const Pose2D next = pose.Compose({seg.v * dt, 0.0, seg.omega * dt});
      cv::line(canvas.image(), canvas.Px(pose.x, pose.y), canvas.Px(next.x, next.y), kRobot, 1, cv::LINE_AA);
      pose = next;
    }
  }
  const Pose2D& s = world.robot_start;
  const cv::Point c = canvas.Px(s.x, s.y);
  cv::circle(canvas.image(), c, canvas.Len(0.36), kRobot, 2, cv::LINE_AA);
  cv::arrowedLine(canvas.image(), c, canvas.Px(s.x + 0.6 * std::cos(s.theta), s.y + 0.6 * std::sin(s.theta)),
                  kRobot, 2, cv::LINE_AA, 0, 0.3);
}

void DrawLegend(const World& world, Canvas& canvas) {
  const int bottom = canvas.image().rows - 30;
  const int left = 40;
  // Scale bar: alternating 1 m blocks up to 5 m.
  const int five = canvas.Len(5.0);
  cv::rectangle(canvas.image(), {left, bottom - 6}, {left + five, bottom}, kText, 1);
  for (int m = 0; m < 5; m += 2) {
    cv::rectangle(canvas.image(), {left + canvas.Len(m), bottom - 6}, {left + canvas.Len(m + 1), bottom},
                  kText, cv::FILLED);
  }
  canvas.Text("5 m", {left + five + 6, bottom}, 0.45, kText);
  char size[64];
  std::snprintf(size, sizeof(size), "   %.0f x %.0f m, 1 m grid", world.floor_max.x() - world.floor_min.x(),
                world.floor_max.y() - world.floor_min.y());
  canvas.Text((world.name.empty() ? world.file : world.name) + size, {left + five + 50, bottom}, 0.45,
              kText);
  canvas.Text("green: robot start and scripted path   colours: people paths (dot = pause)   "
              "orange: doors (dark = state at t=0)   hatched: holes   light: earlier placements",
              {left, bottom + 20}, 0.38, kText);
}

}  // namespace

Status RenderWorldPng(const World& world, const std::string& png_file,
                      const WorldRenderConfig& config) {
  Canvas canvas(world, config);
  DrawFloor(world, canvas);
  DrawObjects(world, canvas);
  DrawPeople(world, canvas);
  DrawRobot(world, canvas);
  DrawLegend(world, canvas);
  try {
    if (!cv::imwrite(png_file, canvas.image())) {
      return Error{png_file + ": cannot write the PNG (check the folder exists and is writable)"};
    }
  } catch (const cv::Exception& e) {
    return Error{png_file + ": cannot write the PNG (" + e.what() + ")"};
  }
  return Ok{};
}

}  // namespace dynamap::robotio::sim
