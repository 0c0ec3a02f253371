#include "dynamap/app/runtime/FrameQueue.hpp"

#include <gtest/gtest.h>

namespace dynamap::app::runtime {
namespace {

CapturedFrame Frame(int sensor, std::int64_t stamp) {
  CapturedFrame f;
  f.depth.sensor_id = sensor;
  f.depth.stamp_ns = stamp;
  return f;
}

TEST(FrameQueue, KeepsTheNewestFramePerKinectAndCountsTheRestAsDropped) {
  FrameQueue queue;
  queue.Push(Frame(0, 10));
  queue.Push(Frame(1, 12));
  queue.Push(Frame(0, 20));  // Replaces the unprocessed frame at 10.
  const auto frames = queue.TakeAll(std::chrono::milliseconds(0));
  ASSERT_EQ(frames.size(), 2u);
  EXPECT_EQ(frames[0].depth.stamp_ns, 12);  // Ordered by capture time.
  EXPECT_EQ(frames[1].depth.stamp_ns, 20);
  EXPECT_EQ(queue.delivered(), 3);
  EXPECT_EQ(queue.dropped(), 1);
}

TEST(FrameQueue, TakeAllTimesOutEmptyAndCloseWakesTheConsumer) {
  FrameQueue queue;
  EXPECT_TRUE(queue.TakeAll(std::chrono::milliseconds(5)).empty());
  queue.Close();
  EXPECT_TRUE(queue.TakeAll(std::chrono::hours(1)).empty());
}

}  // namespace
}  // namespace dynamap::app::runtime
