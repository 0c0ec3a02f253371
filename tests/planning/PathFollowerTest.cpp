// Path following: limits, turning in place, slowing near obstacles, reaching the goal.
#include <gtest/gtest.h>

#include <cmath>

#include "dynamap/planning/PathFollower.hpp"

namespace dynamap::planning {
namespace {

robotio::Pose2D Drive(const robotio::Pose2D& p, const robotio::VelocityCommand& c, double dt) {
  return p.Compose({c.v * dt, 0.0, c.omega * dt});
}

TEST(PathFollower, FollowsAnLShapedPathToTheGoalWithinLimits) {
  PathFollower follower;
  const PathFollowerConfig& cfg = follower.config();
  follower.SetPath({{0.0, 0.0}, {3.0, 0.0}, {3.0, 2.0}});
  robotio::Pose2D pose;
  robotio::VelocityCommand last;
  const double dt = 0.05;
  bool reached = false;
  double max_cross_track = 0.0;
  for (int i = 0; i < 400 && !reached; ++i) {
    const FollowerOutput out = follower.Step(pose, 1.0, dt);
    reached = out.goal_reached;
    EXPECT_LE(out.command.v, cfg.max_speed_mps + 1e-9);
    EXPECT_GE(out.command.v, 0.0);
    EXPECT_LE(std::abs(out.command.omega), cfg.max_yaw_rate_radps + 1e-9);
    EXPECT_LE(std::abs(out.command.v - last.v), cfg.max_accel_mps2 * dt + 1e-9);
    EXPECT_LE(std::abs(out.command.omega - last.omega), cfg.max_yaw_accel_radps2 * dt + 1e-9);
    max_cross_track = std::max(max_cross_track, out.cross_track_m);
    last = out.command;
    pose = Drive(pose, out.command, dt);
  }
  ASSERT_TRUE(reached);
  EXPECT_LE(std::hypot(pose.x - 3.0, pose.y - 2.0), cfg.goal_tolerance_m + 0.02);
  EXPECT_LT(max_cross_track, 0.5);
}

TEST(PathFollower, TurnsInPlaceWhenThePathIsBehind) {
  PathFollower follower;
  follower.SetPath({{0.0, 0.0}, {-2.0, 0.0}});
  FollowerOutput out;
  for (int i = 0; i < 10; ++i) out = follower.Step({0.0, 0.0, 0.0}, 1.0, 0.05);
  EXPECT_DOUBLE_EQ(out.command.v, 0.0);
  EXPECT_GT(std::abs(out.command.omega), 0.5);
}

TEST(PathFollower, SlowsDownNearObstaclesToACreep) {
  const auto cruise = [](double clearance) {
    PathFollower follower;
    follower.SetPath({{0.0, 0.0}, {10.0, 0.0}});
    FollowerOutput out;
    for (int i = 0; i < 100; ++i) out = follower.Step({0.0, 0.0, 0.0}, clearance, 0.05);
    return out.command.v;
  };
  EXPECT_NEAR(cruise(2.0), 1.0, 1e-9);
  EXPECT_LT(cruise(0.3), 0.6);
  // At the inflated edge it creeps on (the guard stops for real contact).
  EXPECT_NEAR(cruise(0.02), PathFollowerConfig{}.creep_speed_mps, 1e-9);
}

TEST(PathFollower, EmptyPathCommandsStandstill) {
  PathFollower follower;
  const FollowerOutput out = follower.Step({1.0, 1.0, 0.0}, 1.0, 0.05);
  EXPECT_FALSE(out.goal_reached);
  EXPECT_DOUBLE_EQ(out.command.v, 0.0);
  EXPECT_DOUBLE_EQ(out.command.omega, 0.0);
}

TEST(PathFollower, TurnsInPlaceToFaceTheLookAtPointBeforeReportingTheGoal) {
  PathFollower follower;
  const PathFollowerConfig& cfg = follower.config();
  // Drive 2 m east, then face a point due north of the goal.
  follower.SetPath({{0.0, 0.0}, {2.0, 0.0}}, Eigen::Vector2d(2.0, 3.0));
  robotio::Pose2D pose;
  const double dt = 0.05;
  bool reached = false;
  bool faced = false;
  for (int i = 0; i < 600 && !reached; ++i) {
    const FollowerOutput out = follower.Step(pose, 1.0, dt);
    reached = out.goal_reached;
    if (out.facing) {
      faced = true;
      EXPECT_EQ(out.command.v, 0.0);  // Turning on the spot, not driving off the viewpoint.
    }
    pose = Drive(pose, out.command, dt);
  }
  ASSERT_TRUE(reached);
  EXPECT_TRUE(faced);
  EXPECT_LE(std::hypot(pose.x - 2.0, pose.y), cfg.goal_tolerance_m + 0.02);
  EXPECT_LE(std::abs(robotio::WrapAngle(pose.theta - M_PI / 2)), cfg.face_tolerance_rad + 0.05);
  // Once faced, the goal stays reached: no second turn.
  const FollowerOutput again = follower.Step(pose, 1.0, dt);
  EXPECT_TRUE(again.goal_reached);
  EXPECT_FALSE(again.facing);
}

}  // namespace
}  // namespace dynamap::planning
