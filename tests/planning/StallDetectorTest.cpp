#include "dynamap/planning/StallDetector.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace dynamap::planning {
namespace {

constexpr double kDt = 0.05;  // The control rate, 20 Hz.

// Steps the detector for `seconds` at command `v`, the base moving `progress` of it along
// x from `*x`; returns how many steps reported a stall.
int Drive(StallDetector* detector, double v, double progress, double seconds, double* x) {
  int stalls = 0;
  for (int i = 0; i < static_cast<int>(std::lround(seconds / kDt)); ++i) {
    *x += progress * v * kDt;
    stalls += detector->Update({*x, 0.0, 0.0}, v, kDt) ? 1 : 0;
  }
  return stalls;
}

TEST(StallDetector, ABaseThatFollowsItsCommandsIsNotStalled) {
  StallDetector detector;
  double x = 0.0;
  EXPECT_EQ(Drive(&detector, 0.5, 1.0, 10.0, &x), 0);
  // Lagging behind the command (acceleration) is not a stall either.
  EXPECT_EQ(Drive(&detector, 0.5, 0.5, 5.0, &x), 0);
}

TEST(StallDetector, ABaseThatDoesNotMoveWhileCommandedIsStalledOnceAWindowHasPassed) {
  StallDetector detector;
  double x = 0.0;
  ASSERT_EQ(Drive(&detector, 0.5, 1.0, 2.0, &x), 0);
  // Pressed against something: the pose stays while the command asks for 0.5 m/s.
  int first = -1;
  for (int i = 0; i < 40 && first < 0; ++i) {
    if (detector.Update({x, 0.0, 0.0}, 0.5, kDt)) first = i;
  }
  // Moved 0.5 m/s for the part of the window before the contact: a stall once less than a
  // quarter of what was commanded over the last second was covered.
  ASSERT_GE(first, 0);
  EXPECT_GE(first * kDt, 0.7);
  EXPECT_LE(first * kDt, 1.0);
  // Reported once, then judged afresh over a whole new window.
  double still = x;
  EXPECT_EQ(Drive(&detector, 0.5, 0.0, 0.9, &still), 0);
  EXPECT_EQ(Drive(&detector, 0.5, 0.0, 0.2, &still), 1);
}

TEST(StallDetector, StandingStillTurningInPlaceOrCreepingIsNotAStall) {
  StallDetector detector;
  double x = 0.0;
  EXPECT_EQ(Drive(&detector, 0.0, 0.0, 5.0, &x), 0);   // Commanded to stand.
  EXPECT_EQ(Drive(&detector, 0.05, 0.0, 1.5, &x), 0);  // 0.075 m over 1.5 s: too little to judge.
}

TEST(StallDetector, ABaseBlockedWhileBackingOffIsStalledToo) {
  StallDetector detector;
  double x = 0.0;
  EXPECT_EQ(Drive(&detector, -0.15, 0.1, 1.5, &x), 1);
}

TEST(StallDetector, TheObstacleLiesOnTheFootprintEdgeTheBaseWasDrivingTowards) {
  const robotio::Pose2D pose{1.0, 2.0, M_PI / 2};  // Facing +y.
  const auto ahead = StallObstacle(pose, 0.36, 1.0);
  ASSERT_FALSE(ahead.empty());
  for (const Eigen::Vector2d& p : ahead) {
    EXPECT_NEAR((p - Eigen::Vector2d(1.0, 2.0)).norm(), 0.39, 1e-9);
    EXPECT_GT(p.y(), 2.0 + 0.39 * std::cos(0.7) - 1e-9);  // Within 0.7 rad of straight ahead.
  }
  const auto behind = StallObstacle(pose, 0.36, -1.0);
  for (const Eigen::Vector2d& p : behind) EXPECT_LT(p.y(), 2.0);
}

}  // namespace
}  // namespace dynamap::planning
