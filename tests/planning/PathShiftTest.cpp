// The path shift off obstacles seen lately: where it shifts, where it does not, and a base
// whose map pose is 0.12 m off driving through a 0.9 m doorway.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamap/planning/ObstacleMemory.hpp"
#include "dynamap/planning/PathFollower.hpp"
#include "dynamap/planning/PathShift.hpp"

namespace dynamap::planning {
namespace {

constexpr double kFootprint = 0.36;

// Surface points, 2 cm apart, of a 0.12 m thick wall along y = 0 with a doorway of
// `width` centred at x = `centre` (the office's doors).
std::vector<Eigen::Vector2d> WallWithDoorway(double centre, double width) {
  std::vector<Eigen::Vector2d> points;
  const double half = 0.5 * width;
  for (double x = -3.0; x <= 3.0; x += 0.02) {
    if (std::abs(x - centre) < half) continue;
    points.emplace_back(x, 0.06);
    points.emplace_back(x, -0.06);
  }
  for (double y = -0.06; y <= 0.06; y += 0.02) {  // The posts' end faces.
    points.emplace_back(centre - half, y);
    points.emplace_back(centre + half, y);
  }
  return points;
}

double Clearance(const Eigen::Vector2d& centre, const std::vector<Eigen::Vector2d>& obstacles) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& o : obstacles) nearest = std::min(nearest, (o - centre).norm());
  return nearest - kFootprint;
}

const std::vector<Eigen::Vector2d> kPathSouth = {{0.0, 2.0}, {0.0, -2.0}};

TEST(PathShift, MovesAPathThroughADoorwayOffByADecimetreToTheDoorwaysMiddle) {
  // The doorway is seen 0.12 m east of where the map (and so the path) has it.
  const Eigen::Vector2d shift =
      PathShiftTarget(kPathSouth, {0.0, 0.6}, WallWithDoorway(0.12, 0.9), kFootprint, {});
  EXPECT_NEAR(shift.x(), 0.12, 0.03);
  EXPECT_NEAR(shift.y(), 0.0, 0.05);
  EXPECT_GT(Clearance(Eigen::Vector2d(0.0, 0.0) + shift, WallWithDoorway(0.12, 0.9)), 0.05);
}

TEST(PathShift, LeavesAPathThroughTheDoorwaysMiddleAlone) {
  EXPECT_EQ(PathShiftTarget(kPathSouth, {0.0, 0.6}, WallWithDoorway(0.0, 0.9), kFootprint, {}),
            Eigen::Vector2d::Zero());
  // Nor does it shift anything with the doorway still far ahead, or a wall 1 m away.
  EXPECT_EQ(PathShiftTarget(kPathSouth, {0.0, 2.0}, WallWithDoorway(0.12, 0.9), kFootprint, {}),
            Eigen::Vector2d::Zero());
  std::vector<Eigen::Vector2d> wall;
  for (double y = -2.0; y <= 2.0; y += 0.02) wall.emplace_back(1.0, y);
  EXPECT_EQ(PathShiftTarget(kPathSouth, {0.0, 0.0}, wall, kFootprint, {}),
            Eigen::Vector2d::Zero());
}

TEST(PathShift, DoesNotSwerveForSomethingAcrossThePathItCannotClear) {
  // A person's trail across the path: no shift within reach clears it.
  std::vector<Eigen::Vector2d> trail;
  for (double x = -1.5; x <= 1.5; x += 0.05) trail.emplace_back(x, 0.0);
  EXPECT_EQ(PathShiftTarget(kPathSouth, {0.0, 0.6}, trail, kFootprint, {}),
            Eigen::Vector2d::Zero());
}

TEST(PathShift, ShiftsOffOneSideNoFurtherThanTheOtherSideAllows) {
  // A desk edge 2 cm beyond the footprint west of a path running south ...
  std::vector<Eigen::Vector2d> desk;
  for (double y = -1.0; y <= 1.0; y += 0.05) desk.emplace_back(-(kFootprint + 0.02), y);
  const Eigen::Vector2d alone = PathShiftTarget(kPathSouth, {0.0, 0.0}, desk, kFootprint, {});
  EXPECT_NEAR(alone.x(), 0.06, 0.021);  // ... is left until 0.08 m are between them.
  // With a pit's edge (the control worker adds the map's hole cells) 0.1 m beyond the
  // footprint on the east, the shift stops where both are equally near.
  std::vector<Eigen::Vector2d> both = desk;
  for (double y = -1.0; y <= 1.0; y += 0.05) both.emplace_back(kFootprint + 0.1, y);
  const Eigen::Vector2d bounded = PathShiftTarget(kPathSouth, {0.0, 0.0}, both, kFootprint, {});
  EXPECT_NEAR(bounded.x(), 0.04, 0.021);
  EXPECT_GE(Clearance(bounded, both), 0.04);
}

TEST(PathShift, TheShiftInForceFollowsItsTargetAtItsRate) {
  PathShiftConfig config;
  config.rate_mps = 0.2;
  PathShift shift(config);
  const std::vector<Eigen::Vector2d> doorway = WallWithDoorway(0.12, 0.9);
  shift.Update(kPathSouth, {0.0, 0.6}, doorway, kFootprint, 0.1);
  EXPECT_NEAR(shift.shift().norm(), 0.02, 1e-9);
  for (int i = 0; i < 20; ++i) shift.Update(kPathSouth, {0.0, 0.6}, doorway, kFootprint, 0.1);
  EXPECT_NEAR(shift.shift().x(), 0.12, 0.03);
  // Nothing near any more: back to none.
  for (int i = 0; i < 20; ++i) shift.Update(kPathSouth, {0.0, 0.6}, {}, kFootprint, 0.1);
  EXPECT_EQ(shift.shift(), Eigen::Vector2d::Zero());
}

// A base drives the path south through the doorway while its map pose is 0.12 m west of
// the truth (as SLAM's was at a mission's door contacts). What it sees goes into the memory
// by exact odometry; the follower gets the map pose moved back by the shift, as the
// control worker does. Returns the footprint's least true clearance to the wall.
double DriveThroughTheDoorway(bool shift_enabled) {
  const std::vector<Eigen::Vector2d> wall = WallWithDoorway(0.0, 0.9);  // True geometry.
  const Eigen::Vector2d error(-0.12, 0.0);                              // Map pose - truth.
  PathShiftConfig config;
  config.enabled = shift_enabled;
  PathShift shift(config);
  ObstacleMemory memory;
  PathFollower follower;
  follower.SetPath(kPathSouth);  // Planned on the map, where the doorway is at x = 0.
  robotio::Pose2D truth{0.12, 2.0, -M_PI / 2};
  const double dt = 0.05;
  double least = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 400; ++i) {
    const auto stamp = static_cast<std::int64_t>(i * dt * 1e9);
    // The Kinects see ahead (0.5 to 2.5 m): robot-height points in base.
    std::vector<Eigen::Vector2d> seen;
    for (const Eigen::Vector2d& o : wall) {
      const robotio::Pose2D p = truth.Inverse().Compose({o.x(), o.y(), 0.0});
      const double range = std::hypot(p.x, p.y);
      if (p.x > 0.0 && range > 0.5 && range < 2.5) seen.emplace_back(p.x, p.y);
    }
    memory.Insert(seen, truth, stamp);  // Odometry: exact here.
    memory.Forget(stamp);
    const robotio::Pose2D believed{truth.x + error.x(), truth.y + error.y(), truth.theta};
    std::vector<Eigen::Vector2d> seen_map;
    for (const Eigen::Vector2d& p : memory.PointsNear(truth, 2.0)) {
      const robotio::Pose2D q = believed.Compose({p.x(), p.y(), 0.0});
      seen_map.emplace_back(q.x, q.y);
    }
    const Eigen::Vector2d s =
        shift.Update(kPathSouth, {believed.x, believed.y}, seen_map, kFootprint, dt);
    const FollowerOutput out =
        follower.Step({believed.x - s.x(), believed.y - s.y(), believed.theta}, 1.0, dt);
    truth = truth.Compose({out.command.v * dt, 0.0, out.command.omega * dt});
    least = std::min(least, Clearance({truth.x, truth.y}, wall));
    if (out.goal_reached) break;
  }
  EXPECT_LT(truth.y, -1.5) << "did not get through";
  return least;
}

TEST(PathShift, ABaseWhoseMapPoseIsOffPassesADoorwayWithoutTouchingIt) {
  EXPECT_LT(DriveThroughTheDoorway(false), 0.0);  // Without the shift: on the door post.
  EXPECT_GT(DriveThroughTheDoorway(true), 0.03);
}

}  // namespace
}  // namespace dynamap::planning
