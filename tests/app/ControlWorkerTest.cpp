#include "dynamap/app/runtime/ControlWorker.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {
namespace {

constexpr double kDt = 0.05;  // 20 Hz.

ControlWorkerConfig NoStartRitual() {
  ControlWorkerConfig config;
  config.initial_still_s = 0.0;
  config.initial_turn_rad = 0.0;
  return config;
}

// A plan 3 m straight ahead of a robot at the origin facing +x, on no grid (no map guard).
Plan StraightAhead() {
  Plan plan;
  plan.has_goal = true;
  plan.goal_map = {3.0, 0.0};
  plan.path_map = {{0.0, 0.0}, {3.0, 0.0}};
  return plan;
}

TEST(ControlWorker, ABasePressedAgainstSomethingUnseenReportsItAndBacksAway) {
  Mediator mediator(0.0, {});
  mediator.plan.Set(StraightAhead());
  ControlWorker control(mediator, robotio::Rig{}, NoStartRitual());
  // Something no Kinect sees stands right in front: the base does not go forward at all,
  // only backward.
  robotio::Pose2D pose;
  double t = 0.0;
  auto tick = [&] {
    mediator.pose_fix.Set({robotio::SecondsToNanos(t), pose, pose});
    const robotio::VelocityCommand c = control.Tick(robotio::SecondsToNanos(t), kDt);
    pose.x += std::min(0.0, c.v) * kDt;
    t += kDt;
    return c;
  };
  int first_backing = -1;
  double top_speed = 0.0;
  for (int i = 0; i < 80 && first_backing < 0; ++i) {
    const robotio::VelocityCommand c = tick();
    top_speed = std::max(top_speed, c.v);
    if (c.v < 0.0) first_backing = i;
  }
  EXPECT_GT(top_speed, 0.3);  // It drove, ...
  ASSERT_GE(first_backing, 0) << "never backed away";
  EXPECT_EQ(mediator.counters.stall_stops.load(), 1);
  // ... noticed within a couple of seconds that it went nowhere, ...
  EXPECT_LE(first_backing * kDt, 2.5);
  // ... and the planner gets the obstacle on the footprint's front edge.
  const std::vector<Eigen::Vector2d> obstacles = mediator.TakeObstacles();
  ASSERT_FALSE(obstacles.empty());
  for (const Eigen::Vector2d& p : obstacles) {
    EXPECT_GT(p.x(), 0.2);
    EXPECT_NEAR(p.norm(), ControlWorkerConfig{}.guard.footprint_radius_m, 0.05);
  }
  // The back-off lasts its time, then the plan is followed again.
  bool forward_again = false;
  for (int i = 0; i < 60 && !forward_again; ++i) forward_again = tick().v > 0.0;
  EXPECT_TRUE(forward_again);
  EXPECT_NEAR(-pose.x, ControlWorkerConfig{}.stall_backoff_s *
                           ControlWorkerConfig{}.guard.backoff_speed_mps, 0.02);
  EXPECT_EQ(mediator.counters.stall_stops.load(), 1);
}

TEST(ControlWorker, ABaseThatMovesAsCommandedIsNotStalled) {
  Mediator mediator(0.0, {});
  mediator.plan.Set(StraightAhead());
  ControlWorker control(mediator, robotio::Rig{}, NoStartRitual());
  robotio::Pose2D pose;
  double t = 0.0;
  for (int i = 0; i < 60; ++i, t += kDt) {
    mediator.pose_fix.Set({robotio::SecondsToNanos(t), pose, pose});
    const robotio::VelocityCommand c = control.Tick(robotio::SecondsToNanos(t), kDt);
    EXPECT_GE(c.v, 0.0) << "at " << t << " s";
    pose.x += c.v * kDt;  // A base that does as it is told.
  }
  EXPECT_GT(pose.x, 1.0);
  EXPECT_EQ(mediator.counters.stall_stops.load(), 0);
  EXPECT_TRUE(mediator.TakeObstacles().empty());
}

}  // namespace
}  // namespace dynamap::app::runtime
