// The odometry-frame memory of robot-height points: placement, range, one point per cell,
// forgetting.
#include <gtest/gtest.h>

#include <cmath>

#include "dynamap/planning/ObstacleMemory.hpp"

namespace dynamap::planning {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

TEST(ObstacleMemory, APointSeenAheadIsBesideTheBaseAfterItDroveAndTurned) {
  ObstacleMemory memory;
  // A post 1 m ahead and 0.45 m to the left of the base at the odometry origin.
  memory.Insert({{1.0, 0.45}}, {0.0, 0.0, 0.0}, 0);
  // The base drove 1 m ahead and turned left by 90 degrees: the post is now on its right.
  const std::vector<Eigen::Vector2d> near = memory.PointsNear({1.0, 0.0, M_PI / 2}, 1.0);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_NEAR(near[0].x(), 0.45, 1e-9);
  EXPECT_NEAR(near[0].y(), 0.0, 1e-9);
  EXPECT_TRUE(memory.PointsNear({3.0, 0.0, 0.0}, 1.0).empty());  // Out of the radius asked.
}

TEST(ObstacleMemory, KeepsTheNewestPointPerCellAndNothingBeyondItsRange) {
  ObstacleMemoryConfig config;
  config.cell_m = 0.05;
  config.range_m = 2.0;
  ObstacleMemory memory(config);
  memory.Insert({{1.001, 0.0}, {1.002, 0.001}, {2.5, 0.0}}, {}, 0);
  EXPECT_EQ(memory.size(), 1u);  // Two in one cell; one beyond the range.
  memory.Insert({{1.04, 0.01}}, {}, kSecond);
  const std::vector<Eigen::Vector2d> near = memory.PointsNear({}, 3.0);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_NEAR(near[0].x(), 1.04, 1e-9);  // The newest sighting, not a cell centre.
  EXPECT_NEAR(near[0].y(), 0.01, 1e-9);
}

TEST(ObstacleMemory, ForgetsWhatWasNotSeenAgainWithinItsKeepTime) {
  ObstacleMemoryConfig config;
  config.keep_s = 8.0;
  ObstacleMemory memory(config);
  memory.Insert({{1.0, 0.0}, {0.0, 1.0}}, {}, 0);
  memory.Insert({{0.0, 1.0}}, {}, 5 * kSecond);  // Seen again.
  memory.Forget(8 * kSecond);
  EXPECT_EQ(memory.size(), 2u);
  memory.Forget(9 * kSecond);
  const std::vector<Eigen::Vector2d> near = memory.PointsNear({}, 3.0);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_NEAR(near[0].y(), 1.0, 1e-9);
  memory.Forget(14 * kSecond);
  EXPECT_EQ(memory.size(), 0u);
}

}  // namespace
}  // namespace dynamap::planning
