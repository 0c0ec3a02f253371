#include "dynamap/app/runtime/ControlWorker.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {
namespace {

constexpr double kDt = 0.05;  // 20 Hz.

// The default control without the start's standing still and look around.
ControlWorkerConfig WithoutTheStart() {
  ControlWorkerConfig config;
  config.initial_still_s = 0.0;
  config.initial_turn_rad = 0.0;
  return config;
}

// A navigable 10 x 4 m grid at 5 cm, the map frame's origin 1 m from its west edge on its
// middle line.
std::shared_ptr<planning::GridMap> FreeGrid() {
  auto map = std::make_shared<planning::GridMap>(200, 80, 0.05, planning::CellState::kNavigable);
  map->origin_x_m = -1.0;
  map->origin_y_m = -2.0;
  return map;
}

// A plan from the origin straight east to (`length_m`, 0), made on `map` (null: no grid,
// so no map guard).
Plan StraightPlan(double length_m, std::shared_ptr<const planning::GridMap> map) {
  Plan plan;
  plan.has_goal = true;
  plan.goal_map = {length_m, 0.0};
  plan.path_map = {{0.0, 0.0}, {length_m, 0.0}};
  plan.map = std::move(map);
  return plan;
}

// The control worker on a plan 3 m straight ahead of a robot at the origin facing +x, on no
// grid (no map guard), without the start's standing still and look around; each step the
// base moves as `moves` lets it.
class ControlOnAStraightPath : public ::testing::Test {
 protected:
  ControlOnAStraightPath()
      : mediator_(0.0, {}), control_(mediator_, robotio::Rig{}, WithoutTheStart()) {
    mediator_.plan.Set(StraightPlan(3.0, nullptr));
  }

  // One control step; the base then covers `moves(v)` metres along x.
  robotio::VelocityCommand Tick(const std::function<double(double)>& moves) {
    mediator_.pose_fix.Set({robotio::SecondsToNanos(t_), pose_, pose_});
    const robotio::VelocityCommand c = control_.Tick(robotio::SecondsToNanos(t_), kDt);
    pose_.x += moves(c.v);
    t_ += kDt;
    return c;
  }

  Mediator mediator_;
  ControlWorker control_;
  robotio::Pose2D pose_;
  double t_ = 0.0;
};

TEST_F(ControlOnAStraightPath, ABasePressedAgainstSomethingUnseenReportsItAndBacksAway) {
  // Something no Kinect sees stands right in front: the base goes backward only.
  const auto held_from_the_front = [](double v) { return std::min(0.0, v) * kDt; };
  int first_backing = -1;
  double top_speed = 0.0;
  for (int i = 0; i < 80 && first_backing < 0; ++i) {
    const robotio::VelocityCommand c = Tick(held_from_the_front);
    top_speed = std::max(top_speed, c.v);
    if (c.v < 0.0) first_backing = i;
  }
  EXPECT_GT(top_speed, 0.3);  // It drove, ...
  ASSERT_GE(first_backing, 0) << "never backed away";
  EXPECT_EQ(mediator_.counters.stall_stops.load(), 1);
  // ... noticed within a couple of seconds that it went nowhere, ...
  EXPECT_LE(first_backing * kDt, 2.5);
  // ... and the planner gets the obstacle on the footprint's front edge.
  const std::vector<Eigen::Vector2d> obstacles = mediator_.TakeObstacles();
  ASSERT_FALSE(obstacles.empty());
  for (const Eigen::Vector2d& p : obstacles) {
    EXPECT_GT(p.x(), 0.2);
    EXPECT_NEAR(p.norm(), ControlWorkerConfig{}.guard.footprint_radius_m, 0.05);
  }
  // The back-off lasts its time, then the plan is followed again.
  bool forward_again = false;
  for (int i = 0; i < 60 && !forward_again; ++i) forward_again = Tick(held_from_the_front).v > 0.0;
  EXPECT_TRUE(forward_again);
  EXPECT_NEAR(-pose_.x, ControlWorkerConfig{}.stall_backoff_s *
                            ControlWorkerConfig{}.guard.backoff_speed_mps, 0.02);
  EXPECT_EQ(mediator_.counters.stall_stops.load(), 1);
}

TEST_F(ControlOnAStraightPath, ABaseThatMovesAsCommandedIsNotStalled) {
  for (int i = 0; i < 60; ++i) {
    EXPECT_GE(Tick([](double v) { return v * kDt; }).v, 0.0) << "at " << t_ << " s";
  }
  EXPECT_GT(pose_.x, 1.0);
  EXPECT_EQ(mediator_.counters.stall_stops.load(), 0);
  EXPECT_TRUE(mediator_.TakeObstacles().empty());
}

TEST(ControlWorker, CruisesAtTheSpeedItsGridClearanceAllowsInTheOpen) {
  // A plan on a free grid with a free clearance grid: the follower is given the grid's
  // clearance (its proximity range), not the footprint radius as when there is no grid.
  Mediator mediator(0.0, {});
  const ControlWorkerConfig config = WithoutTheStart();
  ControlWorker control(mediator, robotio::Rig{}, config);
  Plan plan = StraightPlan(8.0, FreeGrid());
  plan.clearance = std::make_shared<planning::TraversalGrid>(200, 80, 0.0);
  mediator.plan.Set(plan);
  robotio::Pose2D pose;
  double top_speed = 0.0;
  for (int i = 0; i < 100; ++i) {
    const double t = i * kDt;
    mediator.pose_fix.Set({robotio::SecondsToNanos(t), pose, pose});
    const robotio::VelocityCommand c = control.Tick(robotio::SecondsToNanos(t), kDt);
    top_speed = std::max(top_speed, c.v);
    pose.x += c.v * kDt;
  }
  planning::PathFollower reference(config.follower);
  reference.SetPath(plan.path_map);
  double expected = 0.0;
  for (int i = 0; i < 100; ++i) {
    expected = std::max(expected,
                        reference.Step({}, config.cost.proximity_range_m, kDt).command.v);
  }
  EXPECT_NEAR(top_speed, expected, 1e-6);
  EXPECT_GT(top_speed, 0.7);
}

TEST(ControlWorker, AMapGuardHoldThatLastsReportsTheWayAheadBlocked) {
  // The plan runs 3 m east through a wall the map has at 1.0-1.1 m (nothing is there for
  // the Kinects; the path was planned through it). The map guard holds the base short of
  // it; once it has held for map_guard_give_up_s the planner gets the way ahead blocked,
  // and again after as long if nothing changes.
  Mediator mediator(0.0, {});
  const ControlWorkerConfig config = WithoutTheStart();
  ControlWorker control(mediator, robotio::Rig{}, config);
  const std::shared_ptr<planning::GridMap> map = FreeGrid();
  for (int y = 0; y < map->height; ++y) {
    for (const int x : {40, 41}) map->Set({x, y}, planning::CellState::kObstacle);
  }
  mediator.plan.Set(StraightPlan(3.0, map));
  robotio::Pose2D pose;
  double first_held_s = -1.0;
  double first_report_s = -1.0;
  std::vector<Eigen::Vector2d> reported;
  robotio::Pose2D reported_at;
  for (int i = 0; i < 400 && mediator.counters.map_guard_give_ups.load() < 2; ++i) {
    const double t = i * kDt;
    mediator.pose_fix.Set({robotio::SecondsToNanos(t), pose, pose});
    const robotio::VelocityCommand c = control.Tick(robotio::SecondsToNanos(t), kDt);
    pose.x += c.v * kDt;
    if (first_held_s < 0.0 && mediator.counters.map_guard_stops.load() > 0) first_held_s = t;
    const std::vector<Eigen::Vector2d> obstacles = mediator.TakeObstacles();
    if (!obstacles.empty() && first_report_s < 0.0) {
      first_report_s = t;
      reported = obstacles;
      reported_at = pose;
    }
  }
  EXPECT_LT(pose.x + config.guard.footprint_radius_m, 1.0) << "drove into the mapped wall";
  EXPECT_GT(reported_at.x, 0.2);  // It drove up to the wall first.
  ASSERT_GE(first_held_s, 0.0);
  ASSERT_GE(first_report_s, 0.0) << "a hold of " << 400 * kDt << " s was never reported";
  // Not before the hold had lasted its time; not long after (the base creeps up to the
  // wall for a moment before standing).
  EXPECT_GE(first_report_s - first_held_s, config.map_guard_give_up_s - kDt);
  EXPECT_LT(first_report_s - first_held_s, config.map_guard_give_up_s + 3.0);
  // The obstacle stands on the footprint's front edge, between the base and the wall.
  ASSERT_FALSE(reported.empty());
  for (const Eigen::Vector2d& p : reported) {
    EXPECT_GT(p.x(), reported_at.x + 0.2);
    EXPECT_NEAR((p - Eigen::Vector2d(reported_at.x, reported_at.y)).norm(),
                config.guard.footprint_radius_m, 0.05);
  }
  EXPECT_EQ(mediator.counters.map_guard_give_ups.load(), 2);  // Held on: reported again.
}

}  // namespace
}  // namespace dynamap::app::runtime
