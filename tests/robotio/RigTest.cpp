#include "dynamap/robotio/Rig.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "TestPaths.hpp"

namespace dynamap::robotio {
namespace {

constexpr double kDeg = M_PI / 180.0;

Rig TwoKinectRig() {
  Rig rig;
  KinectMount a;
  a.id = "front";
  a.T_base_kinect = MountPose({0.05, 0.02, 0.60}, Eigen::Vector3d(179.0, 8.0, 35.0) * kDeg);
  a.latency_s = 0.1;
  KinectMount b;
  b.id = "rear";
  b.T_base_kinect = MountPose({-0.04, -0.01, 0.46}, Eigen::Vector3d(-178.5, 6.0, -120.0) * kDeg);
  b.intrinsics = Intrinsics{}.Scaled(320, 240);
  b.max_range_m = 4.0;
  rig.kinects = {a, b};
  return rig;
}

TEST(Rig, LevelForwardKinectLooksAlongBaseX) {
  const Eigen::Isometry3d T = MountPose({0, 0, 0.5}, Eigen::Vector3d::Zero());
  // Optical z (forward) is base x; optical y (down) is base -z.
  EXPECT_TRUE((T.linear() * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE((T.linear() * Eigen::Vector3d::UnitY()).isApprox(-Eigen::Vector3d::UnitZ()));
  EXPECT_TRUE((T.linear() * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitY()));
}

TEST(Rig, UpsideDownKinectHasImageDownPointingUp) {
  const Eigen::Isometry3d T = MountPose({0, 0, 0.6}, Eigen::Vector3d(180.0, 0, 0) * kDeg);
  EXPECT_TRUE((T.linear() * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_TRUE((T.linear() * Eigen::Vector3d::UnitY()).isApprox(Eigen::Vector3d::UnitZ()));
}

TEST(Rig, RollPitchYawRoundTrip) {
  const Eigen::Vector3d rpy(0.3, -0.2, 2.5);
  const Eigen::Vector3d back = MountRollPitchYaw(MountPose({0, 0, 0}, rpy));
  EXPECT_NEAR(back.x(), rpy.x(), 1e-12);
  EXPECT_NEAR(back.y(), rpy.y(), 1e-12);
  EXPECT_NEAR(back.z(), rpy.z(), 1e-12);
}

TEST(Rig, SaveThenLoadGivesTheSameRig) {
  const Rig rig = TwoKinectRig();
  const std::string file = test::ScratchDir() + "/rig.yaml";
  ASSERT_TRUE(SaveRig(rig, file).ok());
  auto loaded = LoadRig(file);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  ASSERT_EQ(loaded->kinects.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    const KinectMount& a = rig.kinects[i];
    const KinectMount& b = loaded->kinects[i];
    EXPECT_EQ(a.id, b.id);
    EXPECT_TRUE(a.T_base_kinect.matrix().isApprox(b.T_base_kinect.matrix(), 1e-12));
    EXPECT_EQ(a.intrinsics, b.intrinsics);
    EXPECT_DOUBLE_EQ(a.min_range_m, b.min_range_m);
    EXPECT_DOUBLE_EQ(a.max_range_m, b.max_range_m);
    EXPECT_DOUBLE_EQ(a.latency_s, b.latency_s);
  }
}

TEST(Rig, UnknownKeyNamesTheKeyPath) {
  auto rig = ParseRig("kinects:\n  - id: a\n    translation: [0, 0, 0.5]\n    rpy_deg: [180, 0, 0]\n"
                      "    latnecy_s: 0.1\n",
                      "rig.yaml");
  ASSERT_FALSE(rig.ok());
  EXPECT_NE(rig.error().message.find("rig.yaml"), std::string::npos);
  EXPECT_NE(rig.error().message.find("kinects[0].latnecy_s"), std::string::npos)
      << rig.error().message;
}

TEST(Rig, WrongTypeNamesTheKey) {
  auto rig = ParseRig("kinects:\n  - id: a\n    translation: [0, zero, 0.5]\n    rpy_deg: [180, 0, 0]\n",
                      "rig.yaml");
  ASSERT_FALSE(rig.ok());
  EXPECT_NE(rig.error().message.find("kinects[0].translation"), std::string::npos)
      << rig.error().message;
}

TEST(Rig, OutOfRangeLatencyNamesKeyAndRange) {
  auto rig = ParseRig("kinects:\n  - id: a\n    translation: [0, 0, 0.5]\n    rpy_deg: [180, 0, 0]\n"
                      "    latency_s: 5\n",
                      "rig.yaml");
  ASSERT_FALSE(rig.ok());
  EXPECT_NE(rig.error().message.find("kinects[0].latency_s"), std::string::npos)
      << rig.error().message;
  EXPECT_NE(rig.error().message.find("[-1, 1]"), std::string::npos) << rig.error().message;
}

TEST(Rig, MissingRequiredKeyNamesIt) {
  auto rig = ParseRig("kinects:\n  - id: a\n    rpy_deg: [180, 0, 0]\n", "rig.yaml");
  ASSERT_FALSE(rig.ok());
  EXPECT_NE(rig.error().message.find("kinects[0].translation"), std::string::npos)
      << rig.error().message;
  EXPECT_NE(rig.error().message.find("required"), std::string::npos);
}

TEST(Rig, DuplicateIdsAreRejected) {
  auto rig = ParseRig(
      "kinects:\n  - {id: a, translation: [0, 0, 0.5], rpy_deg: [0, 0, 0]}\n"
      "  - {id: a, translation: [0, 0, 0.4], rpy_deg: [0, 0, 0]}\n",
      "rig.yaml");
  ASSERT_FALSE(rig.ok());
  EXPECT_NE(rig.error().message.find("used by two"), std::string::npos) << rig.error().message;
}

TEST(Rig, MissingFileNamesIt) {
  auto rig = LoadRig("/no/such/rig.yaml");
  ASSERT_FALSE(rig.ok());
  EXPECT_NE(rig.error().message.find("/no/such/rig.yaml"), std::string::npos);
}

}  // namespace
}  // namespace dynamap::robotio
