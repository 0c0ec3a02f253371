// Collision guard on synthetic depth frames of the thesis rig: a person stepping in front
// of the driving robot stops it on the first frame they are inside the protected zone.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "dynamap/planning/CollisionGuard.hpp"
#include "dynamap/planning/TemporaryObstacles.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::planning {
namespace {

struct Person {
  Eigen::Vector2d center;     // m, base frame.
  double radius = 0.25;       // m.
  double height = 1.8;        // m.
};

// Renders what one Kinect of the rig sees: the floor (z = 0) and an optional person
// (a vertical cylinder), at 160 x 120.
robotio::DepthFrame Render(const robotio::KinectMount& mount, int sensor_id,
                           const std::optional<Person>& person) {
  robotio::DepthFrame frame;
  frame.sensor_id = sensor_id;
  frame.width = 160;
  frame.height = 120;
  frame.intrinsics = mount.intrinsics.Scaled(160, 120);
  frame.depth_mm.assign(160 * 120, 0);
  const Eigen::Vector3d o = mount.T_base_kinect.translation();
  const Eigen::Matrix3d R = mount.T_base_kinect.linear();
  const auto& k = frame.intrinsics;
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const Eigen::Vector3d d = R * Eigen::Vector3d((u - k.cx) / k.fx, (v - k.cy) / k.fy, 1.0);
      double t = std::numeric_limits<double>::infinity();  // Optical z of the hit.
      if (d.z() < 0.0) t = -o.z() / d.z();
      if (person) {
        const Eigen::Vector2d oc = o.head<2>() - person->center;
        const Eigen::Vector2d dd = d.head<2>();
        const double a = dd.squaredNorm();
        const double b = 2.0 * oc.dot(dd);
        const double c = oc.squaredNorm() - person->radius * person->radius;
        const double disc = b * b - 4.0 * a * c;
        if (disc >= 0.0) {
          const double hit = (-b - std::sqrt(disc)) / (2.0 * a);
          const double z = o.z() + hit * d.z();
          if (hit > 0.0 && z >= 0.0 && z <= person->height) t = std::min(t, hit);
        }
      }
      if (t >= mount.min_range_m && t <= mount.max_range_m) {
        frame.depth_mm[v * frame.width + u] = static_cast<std::uint16_t>(std::lround(t * 1000.0));
      }
    }
  }
  return frame;
}

GuardVerdict Check(const robotio::Rig& rig, const std::optional<Person>& person, double v) {
  const robotio::DepthFrame f0 = Render(rig.kinects[0], 0, person);
  const robotio::DepthFrame f1 = Render(rig.kinects[1], 1, person);
  robotio::VelocityCommand command;
  command.v = v;
  return CheckCollision({&f0, &f1}, rig, command, CollisionGuardConfig{});
}

robotio::Rig ThesisRig() {
  auto rig = robotio::LoadRig(std::string(DYNAMAP_RESOURCES_DIR) + "/rigs/two_kinects.yaml");
  EXPECT_TRUE(rig) << rig.error().message;
  return *rig;
}

TEST(CollisionGuard, FloorAloneNeverStops) {
  const robotio::Rig rig = ThesisRig();
  EXPECT_FALSE(Check(rig, std::nullopt, 1.0).stop);
}

TEST(CollisionGuard, PersonSteppingInFrontStopsTheRobotWithinOneFrame) {
  const robotio::Rig rig = ThesisRig();
  const CollisionGuardConfig config;
  const double v = 0.8;
  const double radius = config.footprint_radius_m + config.safety_margin_m;
  const double reach = radius + StoppingDistance(v, config);
  // The person walks in from the left at 1.5 m/s across the robot's course, 30 frames/s.
  Person person;
  person.center = {1.1, 1.6};
  bool stopped = false;
  for (int frame = 0; frame < 60 && !stopped; ++frame) {
    person.center.y() -= 1.5 / 30.0;
    // How deep the person is inside the swept corridor (negative: still outside).
    const double depth = std::min(radius - (std::abs(person.center.y()) - person.radius),
                                  reach - (person.center.x() - person.radius));
    const GuardVerdict verdict = Check(rig, person, v);
    if (depth < -0.1) {
      EXPECT_FALSE(verdict.stop) << "frame " << frame << ": stopped while the person is clear";
    }
    if (depth > 0.05) {
      ASSERT_TRUE(verdict.stop) << "frame " << frame << ": person inside, robot still driving";
    }
    stopped = verdict.stop;
    if (stopped) {
      EXPECT_GE(verdict.points_inside, config.min_points);
      EXPECT_DOUBLE_EQ(verdict.recovery.v, 0.0);   // Turns rather than reversing blind ...
      EXPECT_LT(verdict.recovery.omega, 0.0);      // ... away from the person on the left.
    }
  }
  EXPECT_TRUE(stopped);
}

TEST(CollisionGuard, PersonOutsideTheStoppingDistanceDoesNotStopASlowRobot) {
  const robotio::Rig rig = ThesisRig();
  Person person;
  person.center = {1.4, 0.0};  // Front 1.15 m ahead: beyond 0.2 m/s reach, within 1 m/s reach.
  EXPECT_FALSE(Check(rig, person, 0.2).stop);
  EXPECT_TRUE(Check(rig, person, 1.0).stop);  // At full speed it is within braking reach.
}

TEST(CollisionGuard, ReportedObstacleBlocksTheGridUntilItExpires) {
  const robotio::Rig rig = ThesisRig();
  Person person;
  person.center = {0.9, 0.0};
  const GuardVerdict verdict = Check(rig, person, 0.5);
  ASSERT_TRUE(verdict.stop);
  TemporaryObstacles obstacles(5.0);
  const robotio::Pose2D pose{2.0, 1.0, M_PI / 2};  // Robot facing map +y.
  obstacles.Add(verdict.obstacle_base, pose, 10.0);
  GridMap map(100, 100, 0.05, CellState::kNavigable);
  // Obstacle cells lie on the person's visible front, 0.65 m ahead along map +y.
  const auto obstacle_cells = [&](double now_s) {
    const GridMap marked = obstacles.Apply(map, now_s);
    int n = 0;
    for (int i = 0; i < static_cast<int>(marked.cells.size()); ++i) {
      if (marked.cells[i] != CellState::kObstacle) continue;
      ++n;
      const GridIndex c = marked.Cell(i);
      EXPECT_NEAR(marked.CenterY(c.y), 1.0 + 0.9 - person.radius / 2, person.radius / 2 + 0.05);
      EXPECT_NEAR(marked.CenterX(c.x), 2.0, person.radius + 0.05);
    }
    return n;
  };
  EXPECT_GT(obstacle_cells(12.0), 2);
  EXPECT_EQ(obstacle_cells(16.0), 0);
}

}  // namespace
}  // namespace dynamap::planning
