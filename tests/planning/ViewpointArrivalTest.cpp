#include "dynamap/planning/ViewpointArrival.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "dynamap/planning/TargetSelection.hpp"

namespace dynamap::planning {
namespace {

// 5 cm cells from the origin; the viewpoint's centre is at (2.525, 2.525) m and the region
// it looks at lies 2 m south of it.
const GridMap kMap(100, 100, 0.05);
constexpr GridIndex kViewpoint{50, 50};

TargetCandidate Target() {
  TargetCandidate c;
  c.kind = TargetKind::kFrontier;
  c.viewpoint = kViewpoint;
  c.region_center = {50, 10};
  return c;
}

robotio::Pose2D Pose(double dx, double theta) {
  return {kMap.CenterX(kViewpoint.x) + dx, kMap.CenterY(kViewpoint.y), theta};
}

constexpr double kSouth = -M_PI / 2;

TEST(ViewpointArrival, TurnsWhereTheSelectionWouldCallTheViewpointTheRobotsFeet) {
  ViewpointArrival arrival;
  // 0.3 m short, heading east: outside the follower's goal tolerance, inside near_m.
  const robotio::Pose2D pose = Pose(-0.3, 0.0);
  const TargetSelection selection =
      SelectTarget({Target()}, Target(), kMap, kMap.CellAt(pose.x, pose.y), {});
  ASSERT_EQ(selection.too_near.size(), 1u);  // Judged now, it would count as failed.
  EXPECT_TRUE(arrival.StillFacing(kMap, Target(), pose, 100.0));
}

TEST(ViewpointArrival, JudgesTheTargetOnceTheRobotFacesIt) {
  ViewpointArrival arrival;
  EXPECT_TRUE(arrival.StillFacing(kMap, Target(), Pose(0.0, 0.0), 100.0));
  EXPECT_TRUE(arrival.StillFacing(kMap, Target(), Pose(0.0, -1.0), 101.0));
  EXPECT_FALSE(arrival.StillFacing(kMap, Target(), Pose(0.0, kSouth + 0.1), 102.0));
}

TEST(ViewpointArrival, GivesUpTurningAfterTheTimeout) {
  ViewpointArrival arrival({0.35, 0.2, 6.0});
  EXPECT_TRUE(arrival.StillFacing(kMap, Target(), Pose(0.0, 0.0), 100.0));
  EXPECT_TRUE(arrival.StillFacing(kMap, Target(), Pose(0.0, 0.0), 105.9));
  EXPECT_FALSE(arrival.StillFacing(kMap, Target(), Pose(0.0, 0.0), 106.0));
}

TEST(ViewpointArrival, DrivingAwayOrDroppingTheTargetStartsAfresh) {
  ViewpointArrival arrival({0.35, 0.2, 6.0});
  EXPECT_TRUE(arrival.StillFacing(kMap, Target(), Pose(0.0, 0.0), 100.0));
  EXPECT_FALSE(arrival.StillFacing(kMap, Target(), Pose(-0.5, 0.0), 103.0));  // Driving.
  EXPECT_TRUE(arrival.StillFacing(kMap, Target(), Pose(0.0, 0.0), 108.0));   // A new arrival.
  EXPECT_FALSE(arrival.StillFacing(kMap, std::nullopt, Pose(0.0, 0.0), 109.0));
  EXPECT_TRUE(arrival.StillFacing(kMap, Target(), Pose(0.0, 0.0), 114.5));
}

}  // namespace
}  // namespace dynamap::planning
