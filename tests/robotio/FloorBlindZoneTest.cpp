#include "dynamap/robotio/FloorBlindZone.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "TestPaths.hpp"

namespace dynamap::robotio {
namespace {

constexpr double kDeg = M_PI / 180.0;

Rig OneKinect(double height_m, double roll_deg, double pitch_deg) {
  KinectMount k;
  k.T_base_kinect = MountPose({0.0, 0.0, height_m}, Eigen::Vector3d(roll_deg, pitch_deg, 0.0) * kDeg);
  Rig rig;
  rig.kinects = {k};
  return rig;
}

TEST(FloorBlindRadius, StartsWhereTheLowestRowMeetsTheFloorAndWidensToTheCorners) {
  // Pitched 20 deg down at 0.6 m: the lowest image row looks 20 + 24.5 deg down, so it
  // meets the floor 0.6 / tan(44.5 deg) = 0.61 m ahead in the middle, farther at the sides.
  const double centre = 0.6 / std::tan((20.0 + std::atan(239.5 / 525.0) / kDeg) * kDeg);
  const double r = FloorBlindRadius(OneKinect(0.6, 0.0, 20.0));
  EXPECT_GT(r, centre);
  EXPECT_LT(r, 1.3 * centre);
}

TEST(FloorBlindRadius, UpsideDownMountingSeesTheSameFloor) {
  EXPECT_NEAR(FloorBlindRadius(OneKinect(0.6, 180.0, 20.0)),
              FloorBlindRadius(OneKinect(0.6, 0.0, 20.0)), 0.02);
}

TEST(FloorBlindRadius, ShrinksAsTheKinectPitchesDownAndIsZeroWithoutFloorInView) {
  EXPECT_LT(FloorBlindRadius(OneKinect(0.6, 0.0, 35.0)), FloorBlindRadius(OneKinect(0.6, 0.0, 10.0)));
  EXPECT_EQ(FloorBlindRadius(OneKinect(0.6, 0.0, -40.0)), 0.0);
}

TEST(FloorBlindRadius, TheThesisRigSeesNoFloorNearerThanAboutAMetre) {
  auto rig = LoadRig(test::Resource("rigs/two_kinects.yaml"));
  ASSERT_TRUE(rig) << rig.error().message;
  const double r = FloorBlindRadius(*rig);
  EXPECT_GT(r, 0.9);
  EXPECT_LT(r, 1.5);
}

}  // namespace
}  // namespace dynamap::robotio
