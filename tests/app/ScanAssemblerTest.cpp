#include <gtest/gtest.h>

#include "dynamap/app/runtime/ScanAssembler.hpp"

namespace dynamap::app::runtime {
namespace {

constexpr std::int64_t kMs = 1'000'000;

CapturedFrame Frame(int sensor, std::int64_t stamp_ms) {
  CapturedFrame f;
  f.depth.sensor_id = sensor;
  f.depth.stamp_ns = stamp_ms * kMs;
  return f;
}

std::vector<CapturedFrame> Frames(std::initializer_list<std::pair<int, std::int64_t>> list) {
  std::vector<CapturedFrame> out;
  for (const auto& [sensor, stamp_ms] : list) out.push_back(Frame(sensor, stamp_ms));
  return out;
}

// Two Kinects at 30 Hz, half a period apart, arriving one at a time (as the simulator
// delivers them): every scan holds one frame of each.
TEST(ScanAssembler, PairsStaggeredFramesArrivingOneAtATime) {
  ScanAssembler assembler(2, 25 * kMs);
  std::vector<std::vector<CapturedFrame>> scans;
  for (int k = 0; k < 6; ++k) {
    for (const auto& scan : assembler.Add(Frames({{k % 2, 17 * k}}))) scans.push_back(scan);
  }
  ASSERT_EQ(scans.size(), 3u);
  for (const auto& scan : scans) {
    ASSERT_EQ(scan.size(), 2u);
    EXPECT_EQ(scan[0].depth.sensor_id, 0);
    EXPECT_EQ(scan[1].depth.sensor_id, 1);
    EXPECT_EQ(scan[1].depth.stamp_ns - scan[0].depth.stamp_ns, 17 * kMs);
  }
  EXPECT_EQ(assembler.waiting(), 0u);
}

// A frame waits for its partner; when its own Kinect's next frame comes first (the other
// Kinect missed one), it goes alone.
TEST(ScanAssembler, ALoneFrameGoesWhenItsKinectRepeats) {
  ScanAssembler assembler(2, 25 * kMs);
  EXPECT_TRUE(assembler.Add(Frames({{0, 0}})).empty());
  EXPECT_EQ(assembler.waiting(), 1u);
  const auto scans = assembler.Add(Frames({{0, 33}}));
  ASSERT_EQ(scans.size(), 1u);
  ASSERT_EQ(scans[0].size(), 1u);
  EXPECT_EQ(scans[0][0].depth.stamp_ns, 0);
  EXPECT_EQ(assembler.waiting(), 1u);  // The frame at 33 ms waits in turn.
}

// A batch taken late holds several instants (in any order): each becomes its own scan,
// and a partner captured too long after the first frame starts a new one.
TEST(ScanAssembler, SplitsABatchIntoScansByTimeAndSensor) {
  ScanAssembler assembler(2, 25 * kMs);
  const auto scans = assembler.Add(Frames({{1, 17}, {0, 0}, {0, 33}, {1, 90}}));
  ASSERT_EQ(scans.size(), 2u);
  EXPECT_EQ(scans[0].size(), 2u);  // 0 and 17 ms.
  EXPECT_EQ(scans[1].size(), 1u);  // 33 ms: its partner at 90 ms is too late.
  EXPECT_EQ(assembler.waiting(), 1u);
}

// With one Kinect, every frame is a scan at once.
TEST(ScanAssembler, OneKinectScansEveryFrame) {
  ScanAssembler assembler(1, 25 * kMs);
  EXPECT_EQ(assembler.Add(Frames({{0, 0}})).size(), 1u);
  EXPECT_EQ(assembler.Add(Frames({{0, 33}, {0, 66}})).size(), 2u);
  EXPECT_EQ(assembler.waiting(), 0u);
}

}  // namespace
}  // namespace dynamap::app::runtime
