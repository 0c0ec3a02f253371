#include "dynamap/planning/MapGuard.hpp"

#include <gtest/gtest.h>

namespace dynamap::planning {
namespace {

// A 4 x 4 m map with a door post: one obstacle cell whose square spans x, y in [2.0, 2.05).
GridMap PostMap() {
  GridMap map(80, 80, 0.05, CellState::kNavigable);
  map.Set({40, 40}, CellState::kObstacle);
  return map;
}

TEST(DistanceToKnownObstacle, MeasuresToTheNearestCellCentre) {
  const GridMap map = PostMap();
  EXPECT_NEAR(DistanceToKnownObstacle(map, 1.5, 2.025, 1.0), 0.525, 1e-9);
  EXPECT_NEAR(DistanceToKnownObstacle(map, 2.025, 2.025, 1.0), 0.0, 1e-9);
  EXPECT_NEAR(DistanceToKnownObstacle(map, 0.5, 2.025, 1.0), 1.0, 1e-9);  // Beyond the search.
}

TEST(DrivesIntoKnownObstacle, RefusesForwardMotionThatBringsThePostIntoTheFootprint) {
  const GridMap map = PostMap();
  // The post 0.38 m ahead of a 0.36 m footprint: 0.1 m/s for 0.5 s brings it to 0.33 m.
  const robotio::Pose2D facing_post{1.645, 2.025, 0.0};
  EXPECT_TRUE(DrivesIntoKnownObstacle(map, facing_post, {0, 0.1, 0.0}, 0.36, 0.5));
  // Backing away, turning in place or passing with room to spare is fine.
  EXPECT_FALSE(DrivesIntoKnownObstacle(map, facing_post, {0, -0.1, 0.0}, 0.36, 0.5));
  EXPECT_FALSE(DrivesIntoKnownObstacle(map, facing_post, {0, 0.0, 1.0}, 0.36, 0.5));
  const robotio::Pose2D passing{1.645, 1.5, 0.0};
  EXPECT_FALSE(DrivesIntoKnownObstacle(map, passing, {0, 0.1, 0.0}, 0.36, 0.5));
}

TEST(DrivesIntoKnownObstacle, LetsTheRobotLeaveWhenItIsAlreadyTooClose) {
  const GridMap map = PostMap();
  const robotio::Pose2D too_close{1.75, 2.025, M_PI};  // 0.25 m from the post, facing away.
  EXPECT_FALSE(DrivesIntoKnownObstacle(map, too_close, {0, 0.1, 0.0}, 0.36, 0.5));
}

TEST(DrivesIntoKnownObstacle, LetsTheFootprintThroughADoorwayItFits) {
  // A 0.9 m door in a wall along y = 2 m: posts at x < 1.55 and x >= 2.45, robot centred
  // (0.45 m from each post's surface, 0.36 m footprint), driving through along +y.
  GridMap map(80, 80, 0.05, CellState::kNavigable);
  for (int x = 0; x < 80; ++x) {
    if (x < 31 || x >= 49) map.Set({x, 40}, CellState::kObstacle);
  }
  for (double y = 1.5; y < 2.5; y += 0.05) {
    EXPECT_FALSE(DrivesIntoKnownObstacle(map, {2.0, y, M_PI / 2}, {0, 0.3, 0.0}, 0.36, 0.5))
        << "at y = " << y;
    // Off centre by a few centimetres the footprint may touch the margin already: sliding
    // along the doorway is still allowed, turning into a post is not.
    EXPECT_FALSE(DrivesIntoKnownObstacle(map, {1.96, y, M_PI / 2}, {0, 0.1, 0.0}, 0.36, 0.5))
        << "at y = " << y;
  }
  EXPECT_TRUE(
      DrivesIntoKnownObstacle(map, {1.96, 1.8, M_PI / 2 + 0.8}, {0, 0.3, 0.0}, 0.36, 0.5));
}

TEST(DrivesIntoKnownObstacle, RefusesToDriveOverTheEdgeOfAHole) {
  // A stair pit's corner: hole cells at x, y >= 2 m. Driving diagonally past it with the
  // footprint about to reach it is refused, driving along its edge at a distance is not.
  GridMap map(80, 80, 0.05, CellState::kNavigable);
  for (int y = 40; y < 80; ++y) {
    for (int x = 40; x < 80; ++x) map.Set({x, y}, CellState::kHole);
  }
  EXPECT_NEAR(DistanceToKnownObstacle(map, 1.5, 2.025, 1.0), 0.525, 1e-9);
  EXPECT_TRUE(
      DrivesIntoKnownObstacle(map, {1.7, 1.7, M_PI / 4}, {0, 0.3, 0.0}, 0.36, 0.5));
  EXPECT_FALSE(DrivesIntoKnownObstacle(map, {1.5, 2.5, M_PI / 2}, {0, 0.3, 0.0}, 0.36, 0.5));
}

}  // namespace
}  // namespace dynamap::planning
