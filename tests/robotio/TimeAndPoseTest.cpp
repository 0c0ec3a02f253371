#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "TestPaths.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::robotio {
namespace {

TEST(Time, StampsRoundTripExactlyThroughText) {
  for (std::int64_t ns : {0LL, 1LL, 999'999'999LL, 1'311'868'164'363'181'000LL, -5'000'000LL}) {
    const auto parsed = ParseStamp(FormatStamp(ns));
    ASSERT_TRUE(parsed.has_value());
    EXPECT_EQ(*parsed, ns);
  }
}

TEST(Time, ParsesTumStampsWithoutFloatingPointError) {
  EXPECT_EQ(ParseStamp("1311868164.363181"), 1311868164363181000LL);
  EXPECT_EQ(ParseStamp("12"), 12'000'000'000LL);
  EXPECT_FALSE(ParseStamp("12.5x").has_value());
  EXPECT_FALSE(ParseStamp("").has_value());
}

TEST(Pose2D, ComposeThenBetweenRecoversTheDelta) {
  const Pose2D a{1.0, -2.0, 2.8};
  const Pose2D delta{0.4, 0.3, 1.0};
  const Pose2D b = a.Compose(delta);
  const Pose2D back = a.Between(b);
  EXPECT_NEAR(back.x, delta.x, 1e-12);
  EXPECT_NEAR(back.y, delta.y, 1e-12);
  EXPECT_NEAR(back.theta, delta.theta, 1e-12);
  EXPECT_LE(std::abs(b.theta), M_PI);
}

TEST(Pose2D, InterpolatesHeadingAcrossTheWrap) {
  const Pose2D mid = Interpolate({0, 0, 3.0}, {1, 0, -3.0}, 0.5);
  EXPECT_NEAR(std::abs(mid.theta), M_PI, 1e-9);
  EXPECT_NEAR(mid.x, 0.5, 1e-12);
}

TEST(TumTrajectory, WriteThenReadGivesTheSamePoses) {
  Trajectory trajectory;
  for (int i = 0; i < 5; ++i) {
    trajectory.push_back(ToStampedPose(1'000'000'000LL + i * 33'333'333LL, {0.1 * i, 0.2, 0.3 * i}));
  }
  const std::string file = test::ScratchDir() + "/t.tum";
  ASSERT_TRUE(WriteTumTrajectory(trajectory, file).ok());
  auto read = ReadTumTrajectory(file);
  ASSERT_TRUE(read.ok()) << read.error().message;
  ASSERT_EQ(read->size(), trajectory.size());
  for (std::size_t i = 0; i < trajectory.size(); ++i) {
    EXPECT_EQ((*read)[i].stamp_ns, trajectory[i].stamp_ns);
    EXPECT_TRUE((*read)[i].pose.matrix().isApprox(trajectory[i].pose.matrix(), 1e-8));
  }
}

TEST(TumTrajectory, ReadsTheRealFreiburgGroundTruth) {
  auto read = ReadTumTrajectory(test::SharedData("tum/fr2_desk_groundtruth.txt"));
  ASSERT_TRUE(read.ok()) << read.error().message;
  EXPECT_GT(read->size(), 2000u);
}

TEST(TumTrajectory, MalformedLineIsAnErrorNamingFileAndLine) {
  const std::string file = test::ScratchDir() + "/bad.tum";
  std::ofstream(file) << "# header\n1.0 0 0 0 0 0 0 1\n2.0 0 0 zero 0 0 0 1\n";
  auto read = ReadTumTrajectory(file);
  ASSERT_FALSE(read.ok());
  EXPECT_NE(read.error().message.find("bad.tum: line 3"), std::string::npos)
      << read.error().message;
}

}  // namespace
}  // namespace dynamap::robotio
