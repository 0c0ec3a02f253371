// Where the shipped rig's two Kinects see at robot height (top view): ahead between 0.5 m
// and their range, within their combined 120 degrees; not beside, behind, or at a door
// post beside a base standing in a doorway.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dynamap/planning/FieldOfView.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::planning {
namespace {

FieldOfView ShippedFieldOfView() {
  auto rig = robotio::LoadRig(std::string(DYNAMAP_RESOURCES_DIR) + "/rigs/two_kinects.yaml");
  EXPECT_TRUE(static_cast<bool>(rig));
  return FieldOfView(rig ? *rig : robotio::Rig{}, 0.05, 0.95);
}

TEST(FieldOfView, SeesAheadWithinRangeAndTheCombinedFieldOfView) {
  const FieldOfView view = ShippedFieldOfView();
  EXPECT_TRUE(view.Sees({2.0, 0.0}));
  EXPECT_TRUE(view.Sees({1.0, 0.3}));
  EXPECT_TRUE(view.Sees({1.0, -0.3}));
  // The two fields, 29 degrees out from 0.16 m apart, meet about 1.3 m ahead: a narrow
  // wedge straight ahead of the base is seen by neither before that.
  EXPECT_FALSE(view.Sees({1.0, 0.0}));
  EXPECT_TRUE(view.Sees({1.4, 0.0}));
  // 50 degrees to either side: each Kinect looks 29 degrees out and sees 31 a side.
  EXPECT_TRUE(view.Sees({2.0 * std::cos(0.87), 2.0 * std::sin(0.87)}));
  EXPECT_TRUE(view.Sees({2.0 * std::cos(0.87), -2.0 * std::sin(0.87)}));
  EXPECT_FALSE(view.Sees({5.5, 0.0}));  // Beyond 4.5 m.
}

TEST(FieldOfView, DoesNotSeeTooNearBesideOrBehindTheBase) {
  const FieldOfView view = ShippedFieldOfView();
  EXPECT_FALSE(view.Sees({0.4, 0.0}));   // Under 0.5 m from the Kinects (0.12 m ahead).
  EXPECT_FALSE(view.Sees({0.0, 0.45}));  // A door post beside the base in a 0.9 m doorway.
  EXPECT_FALSE(view.Sees({0.0, -0.45}));
  EXPECT_FALSE(view.Sees({0.5, 1.5}));   // 72 degrees to the left.
  EXPECT_FALSE(view.Sees({-2.0, 0.0}));
}

TEST(FieldOfView, ARigWithoutKinectsSeesNothing) {
  const FieldOfView view(robotio::Rig{}, 0.05, 0.95);
  EXPECT_FALSE(view.Sees({2.0, 0.0}));
}

}  // namespace
}  // namespace dynamap::planning
