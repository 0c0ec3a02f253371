// The odometry-frame memory of robot-height points: placement, range, one point per cell,
// forgetting (only while a point could be seen again).
#include <gtest/gtest.h>

#include <cmath>

#include "dynamap/planning/ObstacleMemory.hpp"

namespace dynamap::planning {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

// keep_s 8 s, and the given hidden keep time and range.
ObstacleMemoryConfig KeepConfig(double keep_hidden_s, double range_m = 2.5) {
  ObstacleMemoryConfig config;
  config.keep_s = 8.0;
  config.keep_hidden_s = keep_hidden_s;
  config.range_m = range_m;
  return config;
}

bool NothingInView(const Eigen::Vector2d& /*p_base*/) { return false; }

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

TEST(ObstacleMemory, APointOutOfViewIsKeptUntilItHasBeenInViewForItsKeepTime) {
  ObstacleMemory memory(KeepConfig(60.0));
  // A post 1 m ahead, then 0.4 m beside the base standing in a doorway: out of view.
  memory.Insert({{1.0, 0.0}}, {}, 0);
  const robotio::Pose2D in_doorway{1.0, -0.4, 0.0};
  const auto ahead_only = [](const Eigen::Vector2d& p) { return p.x() > 0.5; };
  for (int s = 1; s <= 30; ++s) memory.Forget(s * kSecond, in_doorway, ahead_only);
  EXPECT_EQ(memory.size(), 1u) << "forgotten out of view";
  const std::vector<Eigen::Vector2d> beside = memory.PointsNear(in_doorway, 1.0);
  ASSERT_EQ(beside.size(), 1u);
  EXPECT_NEAR(beside[0].y(), 0.4, 1e-9);
  // The base backs off until the post is ahead again: it ages from then on.
  const robotio::Pose2D backed_off{0.0, -0.4, 0.0};
  memory.Forget(31 * kSecond, backed_off, ahead_only);
  EXPECT_EQ(memory.size(), 1u);
  memory.Forget(38 * kSecond, backed_off, ahead_only);  // Last hidden at 30 s.
  EXPECT_EQ(memory.size(), 1u);
  memory.Forget(38 * kSecond + 1, backed_off, ahead_only);
  EXPECT_EQ(memory.size(), 0u);
}

TEST(ObstacleMemory, OutOfViewAPointIsKeptAtMostItsHiddenKeepTime) {
  ObstacleMemory memory(KeepConfig(20.0));
  memory.Insert({{0.0, 0.5}}, {}, 0);
  memory.Forget(20 * kSecond, {}, NothingInView);
  EXPECT_EQ(memory.size(), 1u);
  memory.Forget(20 * kSecond + 1, {}, NothingInView);
  EXPECT_EQ(memory.size(), 0u);
  // A hidden keep time under keep_s keeps nothing longer than keep_s, in view or not.
  ObstacleMemory plain(KeepConfig(0.0));
  plain.Insert({{0.0, 0.5}}, {}, 0);
  plain.Forget(8 * kSecond, {}, NothingInView);
  EXPECT_EQ(plain.size(), 1u);
  plain.Forget(8 * kSecond + 1, {}, NothingInView);
  EXPECT_EQ(plain.size(), 0u);
}

TEST(ObstacleMemory, BeyondItsRangeAPointAgesAsIfInView) {
  ObstacleMemory memory(KeepConfig(60.0, 2.5));
  memory.Insert({{1.0, 0.0}}, {}, 0);
  memory.Forget(8 * kSecond + 1, {5.0, 0.0, 0.0}, NothingInView);  // 4 m from the base.
  EXPECT_EQ(memory.size(), 0u);
}

}  // namespace
}  // namespace dynamap::planning
