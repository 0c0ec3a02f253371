// Projection of small synthetic dual maps: a table the robot fits under, a step, a hole,
// narrow and wide doors, and a person who exists only in the dynamic map.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "dynamap/planning/AStar.hpp"
#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/MapProjection.hpp"

namespace dynamap::planning {
namespace {

constexpr double kRes = 0.05;

// An observed scene: everything inside `observed` is known (floor occupied at z in
// [-res, 0), the rest free), static and dynamic boxes occupied, holes without floor.
class BoxWorld : public VoxelMapView {
 public:
  Eigen::AlignedBox2f observed{Eigen::Vector2f(0, 0), Eigen::Vector2f(6, 4)};
  std::vector<Eigen::AlignedBox3f> static_boxes;
  std::vector<Eigen::AlignedBox3f> dynamic_boxes;
  std::vector<Eigen::AlignedBox2f> holes;

  double Resolution() const override { return kRes; }
  VoxelState StaticState(const Eigen::Vector3f& p) const override {
    if (!observed.contains(p.head<2>())) return VoxelState::kUnknown;
    for (const auto& b : static_boxes) {
      if (b.contains(p)) return VoxelState::kOccupied;
    }
    bool in_hole = false;
    for (const auto& h : holes) in_hole = in_hole || h.contains(p.head<2>());
    if (!in_hole && p.z() < 0.0f && p.z() >= -static_cast<float>(kRes)) return VoxelState::kOccupied;
    if (!in_hole && p.z() < -static_cast<float>(kRes)) return VoxelState::kUnknown;  // Under floor.
    return VoxelState::kFree;
  }
  VoxelState DynamicState(const Eigen::Vector3f& p) const override {
    for (const auto& b : dynamic_boxes) {
      if (b.contains(p)) return VoxelState::kOccupied;
    }
    return observed.contains(p.head<2>()) ? VoxelState::kFree : VoxelState::kUnknown;
  }
};

Eigen::AlignedBox3f Box(float x0, float y0, float z0, float x1, float y1, float z1) {
  return {Eigen::Vector3f(x0, y0, z0), Eigen::Vector3f(x1, y1, z1)};
}

CellState At(const BoxWorld& world, double x, double y) {
  return ProjectColumn(world, x, y, ProjectionConfig{});
}

TEST(MapProjection, TableTheRobotFitsUnderIsNotAnObstacleButItsLegsAre) {
  BoxWorld world;
  world.static_boxes.push_back(Box(2.0f, 2.0f, 0.95f, 3.0f, 3.0f, 1.0f));  // Top above 0.9 m.
  world.static_boxes.push_back(Box(2.0f, 2.0f, 0.0f, 2.06f, 2.06f, 0.95f));  // One leg.
  EXPECT_EQ(At(world, 2.5, 2.5), CellState::kNavigable);
  EXPECT_EQ(At(world, 2.025, 2.025), CellState::kObstacle);
  // A lower table (top at 0.7 m) blocks.
  world.static_boxes.push_back(Box(4.0f, 1.0f, 0.7f, 5.0f, 2.0f, 0.75f));
  EXPECT_EQ(At(world, 4.5, 1.5), CellState::kObstacle);
}

TEST(MapProjection, StairStepIsAnObstacleAndALowSillIsNot) {
  BoxWorld world;
  world.static_boxes.push_back(Box(1.0f, 1.0f, 0.0f, 2.0f, 2.0f, 0.17f));  // Ascending stair.
  world.static_boxes.push_back(Box(3.0f, 1.0f, 0.0f, 3.1f, 2.0f, 0.03f));  // Door sill.
  EXPECT_EQ(At(world, 1.5, 1.5), CellState::kObstacle);
  EXPECT_EQ(At(world, 3.05, 1.5), CellState::kNavigable);
  EXPECT_EQ(At(world, 0.5, 0.5), CellState::kNavigable);
}

TEST(MapProjection, MissingFloorWithFreeSpaceBelowIsAHole) {
  BoxWorld world;
  world.holes.push_back({Eigen::Vector2f(4.0f, 2.0f), Eigen::Vector2f(5.0f, 3.0f)});
  EXPECT_EQ(At(world, 4.5, 2.5), CellState::kHole);
  EXPECT_EQ(At(world, 3.5, 2.5), CellState::kNavigable);
  EXPECT_EQ(At(world, 7.0, 2.5), CellState::kUnknown);  // Never observed.
}

TEST(MapProjection, PersonInTheDynamicMapBlocksPlanningOnly) {
  BoxWorld world;
  world.dynamic_boxes.push_back(Box(3.0f, 2.0f, 0.0f, 3.4f, 2.4f, 1.8f));
  EXPECT_EQ(At(world, 3.2, 2.2), CellState::kObstacle);
  EXPECT_EQ(world.StaticState(Eigen::Vector3f(3.2f, 2.2f, 1.0f)), VoxelState::kFree);
}

GridMap Area() {
  GridMap area(120, 80, kRes);
  return area;
}

// Two rooms split by a wall at x = 3 with one door of the given width.
BoxWorld WallWithDoor(float door_width) {
  BoxWorld world;
  world.static_boxes.push_back(Box(2.95f, 0.0f, 0.0f, 3.05f, 2.0f - door_width / 2, 2.5f));
  world.static_boxes.push_back(Box(2.95f, 2.0f + door_width / 2, 0.0f, 3.05f, 4.0f, 2.5f));
  return world;
}

bool PassesDoor(float door_width) {
  MapProjector projector(Area(), ProjectionConfig{});
  projector.ProjectAll(WallWithDoor(door_width));
  CostFieldConfig cost;  // Default robot radius 0.35 m: the robot needs ~0.7 m.
  const TraversalGrid grid = BuildTraversalGrid(projector.map(), cost);
  return AStarSearch(grid, projector.map().CellAt(1.0, 2.0), projector.map().CellAt(5.0, 2.0))
      .found;
}

TEST(MapProjection, NarrowDoorClosesThroughInflationAndAWideOneStaysOpen) {
  EXPECT_FALSE(PassesDoor(0.55f));
  EXPECT_TRUE(PassesDoor(0.9f));
}

TEST(MapProjection, UpdateReprojectsOnlyTouchedColumns) {
  BoxWorld world;
  MapProjector projector(Area(), ProjectionConfig{});
  projector.ProjectAll(world);
  const GridIndex person_cell = projector.map().CellAt(3.2, 2.2);
  const GridIndex other_cell = projector.map().CellAt(1.2, 1.2);
  ASSERT_EQ(projector.map().At(person_cell), CellState::kNavigable);
  // The person steps in at (3.2, 2.2); a box also appears at (1.2, 1.2) but the map update
  // only touched the person's columns.
  world.dynamic_boxes.push_back(Box(3.0f, 2.0f, 0.0f, 3.4f, 2.4f, 1.8f));
  world.static_boxes.push_back(Box(1.0f, 1.0f, 0.0f, 1.4f, 1.4f, 1.0f));
  std::vector<Eigen::Vector2f> touched;
  for (float x = 3.0f; x < 3.4f; x += 0.05f) {
    for (float y = 2.0f; y < 2.4f; y += 0.05f) touched.emplace_back(x + 0.025f, y + 0.025f);
  }
  const std::vector<int> changed = projector.Update(world, touched);
  EXPECT_EQ(changed.size(), 64u);
  EXPECT_EQ(projector.map().At(person_cell), CellState::kObstacle);
  EXPECT_EQ(projector.map().At(other_cell), CellState::kNavigable);  // Not touched yet.
  // The person leaves: the same columns become navigable again.
  world.dynamic_boxes.clear();
  EXPECT_EQ(projector.Update(world, touched).size(), 64u);
  EXPECT_EQ(projector.map().At(person_cell), CellState::kNavigable);
}

TEST(MapProjection, DynamicOnlyObstaclesExpireButStaticOnesStay) {
  // A person's trace stays in the dynamic map until seen free; for the planner it blocks
  // only for dynamic_obstacle_ttl_s, then the floor under it is navigable again.
  BoxWorld world;
  ProjectionConfig config;
  config.dynamic_obstacle_ttl_s = 10.0;
  MapProjector projector(Area(), config);
  projector.ProjectAll(world);
  world.dynamic_boxes.push_back(Box(3.0f, 2.0f, 0.0f, 3.4f, 2.4f, 1.8f));  // Person.
  world.static_boxes.push_back(Box(1.0f, 1.0f, 0.0f, 1.4f, 1.4f, 1.0f));   // Cabinet.
  std::vector<Eigen::Vector2f> touched{{3.225f, 2.225f}, {1.225f, 1.225f}};
  const GridIndex person = projector.map().CellAt(3.225, 2.225);
  const GridIndex cabinet = projector.map().CellAt(1.225, 1.225);
  (void)projector.Update(world, touched, 100.0);
  EXPECT_EQ(projector.map().At(person), CellState::kObstacle);
  // The planner is told which obstacles are the dynamic map's alone: the person, not the
  // cabinet.
  EXPECT_EQ(projector.DynamicObstacleCells(),
            std::vector<int>{projector.map().Index(person)});
  EXPECT_TRUE(projector.ExpireDynamicObstacles(world, 105.0).empty());
  (void)projector.Update(world, touched, 108.0);  // Passed over, not hit: no news.
  EXPECT_EQ(projector.map().At(person), CellState::kObstacle);
  const std::vector<int> released = projector.ExpireDynamicObstacles(world, 110.5);
  ASSERT_EQ(released.size(), 1u);
  EXPECT_EQ(projector.map().At(person), CellState::kNavigable);
  EXPECT_TRUE(projector.DynamicObstacleCells().empty());
  EXPECT_TRUE(projector.ExpireDynamicObstacles(world, 112.0).empty());  // Released once.
  EXPECT_EQ(projector.map().At(cabinet), CellState::kObstacle);
  // Once the trace is seen free and the person steps in again, it blocks afresh.
  world.dynamic_boxes.clear();
  (void)projector.Update(world, touched, 120.0);
  world.dynamic_boxes.push_back(Box(3.0f, 2.0f, 0.0f, 3.4f, 2.4f, 1.8f));
  (void)projector.Update(world, touched, 121.0);
  EXPECT_EQ(projector.map().At(person), CellState::kObstacle);
}

TEST(MapProjection, ADynamicObstacleThatScansKeepHittingStays) {
  // A door closed in front of the robot is dynamic (free, then occupied: Table 4.1); while
  // scans keep hitting it, it stays an obstacle, and it expires only once out of sight.
  BoxWorld world;
  ProjectionConfig config;
  config.dynamic_obstacle_ttl_s = 10.0;
  MapProjector projector(Area(), config);
  projector.ProjectAll(world);
  world.dynamic_boxes.push_back(Box(3.0f, 2.0f, 0.0f, 3.9f, 2.05f, 2.0f));  // Closed door.
  const std::vector<Eigen::Vector2f> door{{3.225f, 2.025f}};
  const GridIndex cell = projector.map().CellAt(3.225, 2.025);
  (void)projector.Update(world, door, 100.0);
  ASSERT_EQ(projector.map().At(cell), CellState::kObstacle);
  for (double t = 101.0; t <= 130.0; t += 1.0) {
    projector.Refresh(door, t);
    (void)projector.Update(world, door, t);
    (void)projector.ExpireDynamicObstacles(world, t);
    ASSERT_EQ(projector.map().At(cell), CellState::kObstacle) << "at t = " << t;
  }
  // Out of sight: released ten seconds after the last hit ...
  EXPECT_TRUE(projector.ExpireDynamicObstacles(world, 139.0).empty());
  EXPECT_EQ(projector.ExpireDynamicObstacles(world, 140.5).size(), 1u);
  EXPECT_EQ(projector.map().At(cell), CellState::kNavigable);
  // ... and an obstacle again as soon as a scan hits it.
  projector.Refresh(door, 150.0);
  (void)projector.Update(world, door, 150.0);
  EXPECT_EQ(projector.map().At(cell), CellState::kObstacle);
}

}  // namespace
}  // namespace dynamap::planning
