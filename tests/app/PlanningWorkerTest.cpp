// The planning worker on a hand-made grid: a room the robot stands in, a wall with a
// doorway, and unknown space beyond it. Where the doorway admits only the squeeze radius
// the published plan into it is marked squeezed, which is what lets the control's map
// guard measure it with the squeeze radius too; where no viewpoint is reachable at all the
// plan names the frontier it passed over.
#include "dynamap/app/runtime/PlanningWorker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {
namespace {

// 8 x 4 m at 5 cm, the map frame's origin (the start) 1 m from the west edge on the middle
// line. Walls all round; a wall 0.1 m thick across at x = 2 m with a doorway on the middle
// line, obstacle cells from `north_m` north of it and `south_m` south of it; floor known to
// x = `known_to_m`, unknown beyond.
std::shared_ptr<const ProjectedGrid> RoomWithADoorway(double north_m, double south_m,
                                                      double known_to_m) {
  auto projected = std::make_shared<ProjectedGrid>();
  planning::GridMap& map = projected->map;
  map = planning::GridMap(160, 80, 0.05);
  map.origin_x_m = -1.0;
  map.origin_y_m = -2.0;
  for (int y = 0; y < map.height; ++y) {
    for (int x = 0; x < map.width; ++x) {
      const double cx = map.CenterX(x);
      const double cy = map.CenterY(y);
      const bool border = x == 0 || y == 0 || y == map.height - 1;
      const bool wall = cx > 2.0 && cx < 2.1 && (cy >= north_m || cy <= -south_m);
      planning::CellState state = planning::CellState::kUnknown;
      if (border || wall) {
        state = planning::CellState::kObstacle;
      } else if (cx < known_to_m) {
        state = planning::CellState::kNavigable;
      }
      map.Set({x, y}, state);
    }
  }
  return projected;
}

// The worker's plan from the start facing east, with the nearest frontier (it inspects
// nothing, so the frontier beyond the doorway is the only target).
Plan PlanThroughTheDoorway(double north_m, double south_m, std::int64_t* squeezed_plans,
                           double known_to_m = 3.5) {
  Mediator mediator(0.0, {});
  mediator.counters.looked_around = true;
  mediator.grid.Set(RoomWithADoorway(north_m, south_m, known_to_m));
  mediator.pose_fix.Set({0, robotio::Pose2D{}, robotio::Pose2D{}});
  PlanningWorkerConfig config;
  config.planning.targets.strategy = "nearest-frontier";
  PlanningWorker worker(mediator, config);
  worker.PlanOnce(1.0);
  *squeezed_plans = mediator.counters.squeezed_plans.load();
  const auto plan = mediator.plan.Get();
  EXPECT_TRUE(plan.has_value());
  return plan ? plan->value : Plan{};
}

TEST(PlanningWorker, APlanOnlyTheSqueezeRadiusFindsIsMarkedSqueezed) {
  // Obstacle cell centres at 0.375 m north and 0.325 m south of the middle line: 0.35 m
  // from the cell centred 0.025 m north, less than the full radius (0.36 m), not less than
  // the squeeze radius (0.335 m).
  std::int64_t squeezed_plans = 0;
  const Plan narrow = PlanThroughTheDoorway(0.35, 0.3, &squeezed_plans);
  ASSERT_TRUE(narrow.has_goal);
  // The frontier's viewpoint is in the doorway (from there the unknown beyond is seen).
  EXPECT_GT(narrow.goal_map.x(), 1.9);
  EXPECT_LT(std::abs(narrow.goal_map.y()), 0.1);
  ASSERT_FALSE(narrow.path_map.empty());
  EXPECT_NEAR((narrow.path_map.back() - narrow.goal_map).norm(), 0.0, 1e-9);
  EXPECT_TRUE(narrow.squeezed);
  EXPECT_EQ(squeezed_plans, 1);
  // A doorway the full radius passes: a viewpoint there too, not squeezed.
  const Plan wide = PlanThroughTheDoorway(0.45, 0.4, &squeezed_plans);
  ASSERT_TRUE(wide.has_goal);
  EXPECT_GT(wide.goal_map.x(), 1.9);
  ASSERT_FALSE(wide.path_map.empty());
  EXPECT_FALSE(wide.squeezed);
  EXPECT_EQ(squeezed_plans, 0);
}

// Beyond a 0.4 m gap, the floor known far enough that the frontier is out of sensor range
// from this side: no target, nothing to do, and the plan names the region it passed over
// (the report and map2d.png show what such a "done" leaves unexplored).
TEST(PlanningWorker, AFrontierNoViewpointReachesIsNamedInThePlan) {
  std::int64_t squeezed_plans = 0;
  const Plan plan = PlanThroughTheDoorway(0.2, 0.2, &squeezed_plans, 6.5);
  EXPECT_FALSE(plan.has_goal);
  EXPECT_EQ(plan.kind, planning::TargetKind::kDone);
  ASSERT_EQ(plan.unreachable_frontiers_map.size(), 1u);
  EXPECT_GT(plan.unreachable_frontiers_map[0].x(), 6.0);
  EXPECT_LT(std::abs(plan.unreachable_frontiers_map[0].y()), 0.5);
  EXPECT_TRUE(plan.blacklisted_frontiers_map.empty());
  // Through the doorway that passes, the same frontier is a target and nothing is left.
  const Plan wide = PlanThroughTheDoorway(0.45, 0.4, &squeezed_plans, 6.5);
  EXPECT_TRUE(wide.has_goal);
  EXPECT_TRUE(wide.unreachable_frontiers_map.empty());
}

}  // namespace
}  // namespace dynamap::app::runtime
