// The RMP driver against the emulated base over a real pseudo-terminal byte stream.
#include <gtest/gtest.h>

#include <limits>

#include "PtyPair.hpp"
#include "RmpEmulator.hpp"
#include "dynamap/robotio/hardware/RmpDriver.hpp"

namespace dynamap::robotio::hardware {
namespace {

using test::PtyPair;
using test::RmpEmulator;
using test::WaitUntil;

class RmpDriverTest : public ::testing::Test {
 protected:
  void SetUp() override {
    config_.device = pty_.slave_path();
    config_.baud = 115200;
  }
  std::unique_ptr<RmpDriver> OpenDriver() {
    auto driver = RmpDriver::Open(config_);
    EXPECT_TRUE(driver.ok()) << (driver.ok() ? "" : driver.error().message);
    return driver.ok() ? std::move(driver).value() : nullptr;
  }
  // Collects odometry until `done` holds for the last reading (or the wait runs out).
  std::vector<OdometryReading> CollectUntil(RmpDriver& driver,
                                            const std::function<bool(const OdometryReading&)>& done) {
    std::vector<OdometryReading> all;
    WaitUntil([&] {
      auto readings = driver.ReadOdometry();
      if (!readings.ok()) return true;
      all.insert(all.end(), readings->begin(), readings->end());
      return !all.empty() && done(all.back());
    });
    return all;
  }
  bool LastCommandIs(const RmpEmulator& emulator, int v, int t) {
    const auto commands = emulator.Commands();
    return !commands.empty() && commands.back().velocity_counts == v &&
           commands.back().turn_counts == t;
  }

  PtyPair pty_;
  RmpConfig config_;
};

TEST_F(RmpDriverTest, OpeningAMissingDeviceNamesIt) {
  config_.device = "/dev/does-not-exist-rmp";
  const auto driver = RmpDriver::Open(config_);
  ASSERT_FALSE(driver.ok());
  EXPECT_NE(driver.error().message.find("/dev/does-not-exist-rmp"), std::string::npos);
  EXPECT_NE(driver.error().message.find("Segway RMP"), std::string::npos);
}

TEST_F(RmpDriverTest, VelocityCommandReachesTheBaseInCounts) {
  RmpEmulator emulator(pty_);
  auto driver = OpenDriver();
  ASSERT_NE(driver, nullptr);
  ASSERT_TRUE(driver->Command({0, 0.5, 0.2}).ok());
  // 0.5 m/s × 401 counts/(m/s) = 200.5 → 201; 0.2 rad/s × 446.9 = 89.38 → 89.
  EXPECT_TRUE(WaitUntil([&] { return LastCommandIs(emulator, 201, 89); }));
  EXPECT_EQ(emulator.bad_command_frames(), 0);
}

TEST_F(RmpDriverTest, CommandsAreClampedToTheConfiguredLimits) {
  RmpEmulator emulator(pty_);
  config_.max_velocity_mps = 0.5;
  auto driver = OpenDriver();
  ASSERT_NE(driver, nullptr);
  ASSERT_TRUE(driver->Command({0, 3.0, 0.0}).ok());
  EXPECT_TRUE(WaitUntil([&] { return LastCommandIs(emulator, 201, 0); }));
}

TEST_F(RmpDriverTest, WheelCountsBecomeCumulativeDistancesFromZero) {
  RmpEmulator emulator(pty_);
  emulator.SetWheelCounts(1'000'000, -500);
  auto driver = OpenDriver();
  ASSERT_NE(driver, nullptr);
  ASSERT_TRUE(WaitUntil([&] { return emulator.status_cycles() > 3; }));
  emulator.SetWheelCounts(1'000'000 + 2 * 40181, -500 - 40181);
  const auto readings =
      CollectUntil(*driver, [](const OdometryReading& r) { return r.left_m > 1.0; });
  ASSERT_FALSE(readings.empty());
  EXPECT_DOUBLE_EQ(readings.front().left_m, 0.0);
  EXPECT_DOUBLE_EQ(readings.back().left_m, 2.0);
  EXPECT_DOUBLE_EQ(readings.back().right_m, -1.0);
  for (std::size_t i = 1; i < readings.size(); ++i) {
    EXPECT_GE(readings[i].stamp_ns, readings[i - 1].stamp_ns);
  }
}

TEST_F(RmpDriverTest, CounterWrapAroundKeepsDistancesContinuous) {
  RmpEmulator emulator(pty_);
  const std::int32_t near_max = std::numeric_limits<std::int32_t>::max() - 100;
  emulator.SetWheelCounts(near_max, 0);
  auto driver = OpenDriver();
  ASSERT_NE(driver, nullptr);
  ASSERT_TRUE(WaitUntil([&] { return emulator.status_cycles() > 3; }));
  // 40181 counts forward crosses INT32_MAX and wraps to negative.
  emulator.SetWheelCounts(static_cast<std::int32_t>(static_cast<std::uint32_t>(near_max) + 40181U), 0);
  const auto readings =
      CollectUntil(*driver, [](const OdometryReading& r) { return r.left_m > 0.5; });
  ASSERT_FALSE(readings.empty());
  EXPECT_DOUBLE_EQ(readings.back().left_m, 1.0);
}

TEST_F(RmpDriverTest, GarbageCorruptAndTruncatedFramesNeverBecomeReadings) {
  RmpEmulator emulator(pty_);
  auto driver = OpenDriver();
  ASSERT_NE(driver, nullptr);
  ASSERT_TRUE(WaitUntil([&] { return emulator.status_cycles() > 3; }));
  emulator.InjectRaw({0xF0, 0x00, 0xF0, 0x55, 0xAA, 0x12, 0xF0, 0xFF, 0x42});
  emulator.InjectCorruptWheelFrame(999'999, 999'999);
  emulator.InjectTruncatedWheelFrame(888'888, 888'888, 12);
  emulator.SetSplitIntoSingleBytes(true);
  emulator.SetWheelCounts(40181, 40181);
  const auto readings =
      CollectUntil(*driver, [](const OdometryReading& r) { return r.left_m > 0.5; });
  ASSERT_FALSE(readings.empty());
  for (const OdometryReading& r : readings) {
    EXPECT_TRUE(r.left_m == 0.0 || r.left_m == 1.0) << r.left_m;
    EXPECT_EQ(r.left_m, r.right_m);
  }
  EXPECT_DOUBLE_EQ(readings.back().left_m, 1.0);
  const RmpLinkStats stats = driver->Stats();
  EXPECT_GE(stats.checksum_errors, 1U);
  EXPECT_GT(stats.skipped_bytes, 0U);
  EXPECT_FALSE(driver->Fault().has_value());
  ASSERT_TRUE(stats.battery_v.has_value());
  EXPECT_DOUBLE_EQ(*stats.battery_v, 72.0);
}

TEST_F(RmpDriverTest, WatchdogStopsTheBaseWhenCommandsStopArriving) {
  RmpEmulator emulator(pty_);
  auto driver = OpenDriver();
  ASSERT_NE(driver, nullptr);
  ASSERT_TRUE(driver->Command({0, 0.5, 0.0}).ok());
  ASSERT_TRUE(WaitUntil([&] { return LastCommandIs(emulator, 201, 0); }));
  // No further Command(): the driver itself must zero the command.
  EXPECT_TRUE(WaitUntil([&] { return LastCommandIs(emulator, 0, 0); }));
  EXPECT_EQ(driver->Stats().watchdog_stops, 1U);
  EXPECT_FALSE(driver->Fault().has_value());
}

TEST_F(RmpDriverTest, SilentBaseIsAFaultAndTheBaseIsCommandedToStop) {
  RmpEmulator emulator(pty_);
  auto driver = OpenDriver();
  ASSERT_NE(driver, nullptr);
  ASSERT_TRUE(driver->Command({0, 0.5, 0.0}).ok());
  ASSERT_TRUE(WaitUntil([&] { return LastCommandIs(emulator, 201, 0); }));
  emulator.SetSilent(true);
  // Keep commanding motion, as a running mission would.
  ASSERT_TRUE(WaitUntil([&] {
    (void)driver->Command({0, 0.5, 0.0});
    return driver->Fault().has_value();
  }));
  EXPECT_NE(driver->Fault()->message.find("no status"), std::string::npos);
  EXPECT_TRUE(WaitUntil([&] { return LastCommandIs(emulator, 0, 0); }));
  EXPECT_FALSE(driver->Command({0, 0.5, 0.0}).ok());
}

TEST_F(RmpDriverTest, UnplugMidStreamDeliversWhatArrivedThenAnErrorNamingTheDevice) {
  auto emulator = std::make_unique<RmpEmulator>(pty_);
  auto driver = OpenDriver();
  ASSERT_NE(driver, nullptr);
  emulator->SetWheelCounts(40181, 40181);
  ASSERT_TRUE(WaitUntil([&] { return emulator->status_cycles() > 5; }));
  ASSERT_TRUE(driver->Command({0, 0.3, 0.0}).ok());
  emulator->Unplug();
  emulator.reset();
  ASSERT_TRUE(WaitUntil([&] { return driver->Fault().has_value(); }));
  auto first = driver->ReadOdometry();
  ASSERT_TRUE(first.ok());
  EXPECT_FALSE(first->empty());
  auto second = driver->ReadOdometry();
  ASSERT_FALSE(second.ok());
  EXPECT_NE(second.error().message.find(pty_.slave_path()), std::string::npos);
  const Status command = driver->Command({0, 0.3, 0.0});
  ASSERT_FALSE(command.ok());
}

}  // namespace
}  // namespace dynamap::robotio::hardware
