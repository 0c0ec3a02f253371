#include <gtest/gtest.h>

#include <atomic>
#include <thread>

#include "dynamap/app/runtime/LatestValue.hpp"
#include "dynamap/app/runtime/MissionClock.hpp"
#include "dynamap/app/runtime/RunControl.hpp"

namespace dynamap::app::runtime {
namespace {

using namespace std::chrono_literals;

TEST(LatestValue, ReadersSeeTheNewestValueAndItsVersion) {
  LatestValue<int> slot;
  EXPECT_FALSE(slot.Get().has_value());
  slot.Set(3);
  slot.Set(5);
  const auto latest = slot.Get();
  ASSERT_TRUE(latest.has_value());
  EXPECT_EQ(latest->value, 5);
  EXPECT_EQ(latest->version, 2u);
}

TEST(LatestValue, WaitNewerReturnsWhenAWriterPublishes) {
  LatestValue<int> slot;
  slot.Set(1);
  std::thread writer([&] {
    std::this_thread::sleep_for(20ms);
    slot.Set(2);
  });
  const auto newer = slot.WaitNewer(1, 5000ms);
  writer.join();
  ASSERT_TRUE(newer.has_value());
  EXPECT_EQ(newer->value, 2);
}

TEST(LatestValue, WaitNewerTimesOutWithoutANewValue) {
  LatestValue<int> slot;
  slot.Set(1);
  EXPECT_FALSE(slot.WaitNewer(1, 10ms).has_value());
}

TEST(RunControl, FollowsTheMissionStateMachine) {
  RunControl control;
  EXPECT_EQ(control.state(), MissionState::kIdle);
  EXPECT_FALSE(control.Pause());
  EXPECT_TRUE(control.Start());
  EXPECT_FALSE(control.Start());
  EXPECT_FALSE(control.Resume());
  EXPECT_TRUE(control.Pause());
  EXPECT_EQ(control.state(), MissionState::kPaused);
  EXPECT_TRUE(control.Resume());
  EXPECT_TRUE(control.Stop());
  EXPECT_TRUE(control.stopping());
  EXPECT_FALSE(control.Stop());
}

TEST(RunControl, StopReleasesAPausedWorker) {
  RunControl control;
  control.Start();
  control.Pause();
  std::atomic<bool> result{true};
  std::thread worker([&] { result = control.WaitWhilePaused(); });
  std::this_thread::sleep_for(10ms);
  control.Stop();
  worker.join();
  EXPECT_FALSE(result.load());
}

TEST(RunControl, SleepEndsEarlyOnStop) {
  RunControl control;
  control.Start();
  std::thread stopper([&] {
    std::this_thread::sleep_for(10ms);
    control.Stop();
  });
  EXPECT_FALSE(control.SleepFor(std::chrono::hours(1)));
  stopper.join();
}

TEST(MissionClock, WaitersWakeWhenSimulatedTimeReachesTheirTarget) {
  RunControl control;
  control.Start();
  MissionClock clock(1000.0);
  std::atomic<std::int64_t> woke_at{-1};
  std::thread waiter([&] {
    if (clock.WaitUntil(50'000'000, control)) woke_at = clock.now_ns();
  });
  for (std::int64_t t = 0; t <= 100'000'000; t += 10'000'000) clock.AdvanceTo(t);
  waiter.join();
  EXPECT_GE(woke_at.load(), 50'000'000);
}

TEST(MissionClock, WaitEndsWhenTheMissionStops) {
  RunControl control;
  control.Start();
  MissionClock clock(1.0);
  std::thread stopper([&] {
    std::this_thread::sleep_for(10ms);
    control.Stop();
    clock.WakeAll();
  });
  EXPECT_FALSE(clock.WaitUntil(1'000'000'000'000, control));
  stopper.join();
}

TEST(MissionClock, PacesSimulatedTimeAtTheRequestedSpeed) {
  MissionClock clock(10.0);  // 0.5 s simulated should take about 50 ms of wall time.
  const auto start = std::chrono::steady_clock::now();
  for (std::int64_t t = 0; t <= 500'000'000; t += 50'000'000) clock.AdvanceTo(t);
  const auto elapsed = std::chrono::steady_clock::now() - start;
  // A lower bound only: pacing must not run ahead of the requested speed.
  EXPECT_GE(elapsed, 45ms);
}

}  // namespace
}  // namespace dynamap::app::runtime
