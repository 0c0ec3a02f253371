// The Xsens MT framing and the gyro driver against the emulated MTi over a pseudo-terminal.
#include <gtest/gtest.h>

#include <cmath>

#include "PtyPair.hpp"
#include "XsensEmulator.hpp"
#include "dynamap/robotio/hardware/XsensImu.hpp"
#include "dynamap/robotio/hardware/XsensProtocol.hpp"

namespace dynamap::robotio::hardware {
namespace {

using test::PtyPair;
using test::WaitUntil;
using test::XsensEmulator;

TEST(XsensProtocol, GoToMeasurementMatchesTheDocumentedBytes) {
  EXPECT_EQ(EncodeXsensMessage({kXsensGoToMeasurement, {}}),
            (std::vector<std::uint8_t>{0xFA, 0xFF, 0x10, 0x00, 0xF1}));
}

TEST(XsensProtocol, ExtendedLengthMessagesRoundTrip) {
  XsensMessage big{0x36, std::vector<std::uint8_t>(300, 0xFA)};
  const auto bytes = EncodeXsensMessage(big);
  EXPECT_EQ(bytes[3], 0xFF);
  EXPECT_EQ(bytes, XsensEmulator::Message(0x36, big.data));
  XsensFrameParser parser;
  const auto messages = parser.Feed(bytes);
  ASSERT_EQ(messages.size(), 1U);
  EXPECT_EQ(messages[0].data, big.data);
}

TEST(XsensProtocol, ParserSkipsNoiseAndBadChecksumsAcrossSplitFeeds) {
  std::vector<std::uint8_t> stream = {0xFA, 0x00, 0xFA, 0x01, 0x36};
  auto corrupt = XsensEmulator::MtData2(1, {9.0F, 9.0F, 9.0F});
  corrupt.back() ^= 0x01;
  stream.insert(stream.end(), corrupt.begin(), corrupt.end());
  const auto good = XsensEmulator::MtData2(2, {0.5F, -0.25F, 1.5F});
  stream.insert(stream.end(), good.begin(), good.end());
  XsensFrameParser parser;
  std::vector<XsensMessage> messages;
  for (std::size_t i = 0; i < stream.size(); i += 7) {
    const auto end = stream.begin() + static_cast<std::ptrdiff_t>(std::min(stream.size(), i + 7));
    for (auto& m : parser.Feed({stream.begin() + static_cast<std::ptrdiff_t>(i), end})) {
      messages.push_back(m);
    }
  }
  ASSERT_EQ(messages.size(), 1U);
  const XsensDecodeResult decoded = DecodeXsensMtData2(messages[0].data);
  ASSERT_FALSE(decoded.problem.has_value());
  EXPECT_EQ(*decoded.sample.packet_counter, 2);
  EXPECT_EQ(*decoded.sample.sample_time_fine, 200U);
  EXPECT_DOUBLE_EQ((*decoded.sample.rate_of_turn)[1], -0.25);
  EXPECT_GE(parser.counters().checksum_errors, 1U);
}

TEST(XsensProtocol, TruncatedMtData2PacketIsReported) {
  auto message = XsensEmulator::MtData2(1, {1.0F, 2.0F, 3.0F});
  std::vector<std::uint8_t> payload(message.begin() + 4, message.end() - 1);
  payload.resize(payload.size() - 5);
  const XsensDecodeResult decoded = DecodeXsensMtData2(payload);
  ASSERT_TRUE(decoded.problem.has_value());
  EXPECT_NE(decoded.problem->find("0x8020"), std::string::npos);
}

class XsensImuTest : public ::testing::Test {
 protected:
  void SetUp() override { config_.device = pty_.slave_path(); }
  std::unique_ptr<XsensImu> OpenImu() {
    auto imu = XsensImu::Open(config_);
    EXPECT_TRUE(imu.ok()) << (imu.ok() ? "" : imu.error().message);
    return imu.ok() ? std::move(imu).value() : nullptr;
  }
  std::vector<ImuReading> CollectUntil(XsensImu& imu,
                                       const std::function<bool(const ImuReading&)>& done) {
    std::vector<ImuReading> all;
    WaitUntil([&] {
      auto readings = imu.ReadImu();
      if (!readings.ok()) return true;
      all.insert(all.end(), readings->begin(), readings->end());
      return !all.empty() && done(all.back());
    });
    return all;
  }

  PtyPair pty_;
  XsensImuConfig config_;
};

TEST_F(XsensImuTest, MissingDeviceErrorNamesIt) {
  config_.device = "/dev/does-not-exist-imu";
  const auto imu = XsensImu::Open(config_);
  ASSERT_FALSE(imu.ok());
  EXPECT_NE(imu.error().message.find("/dev/does-not-exist-imu"), std::string::npos);
}

TEST_F(XsensImuTest, AsksTheDeviceToMeasureAndDeliversRates) {
  XsensEmulator emulator(pty_);
  emulator.SetRate(0.1F, 0.2F, 0.3F);
  auto imu = OpenImu();
  ASSERT_NE(imu, nullptr);
  const auto readings = CollectUntil(*imu, [](const ImuReading&) { return true; });
  ASSERT_FALSE(readings.empty());
  EXPECT_FLOAT_EQ(static_cast<float>(readings.back().wz), 0.3F);
  EXPECT_FLOAT_EQ(static_cast<float>(readings.back().wx), 0.1F);
  const auto mids = emulator.ReceivedMids();
  ASSERT_FALSE(mids.empty());
  EXPECT_EQ(mids.front(), kXsensGoToMeasurement);
}

TEST_F(XsensImuTest, UpsideDownMountIsRotatedIntoTheBaseFrame) {
  XsensEmulator emulator(pty_);
  emulator.SetRate(0.1F, 0.2F, 0.3F);
  emulator.SetDoublePrecision(true);
  config_.mount_rpy_deg = Eigen::Vector3d(180.0, 0.0, 0.0);
  auto imu = OpenImu();
  ASSERT_NE(imu, nullptr);
  const auto readings = CollectUntil(*imu, [](const ImuReading&) { return true; });
  ASSERT_FALSE(readings.empty());
  EXPECT_NEAR(readings.back().wx, 0.1, 1e-6);
  EXPECT_NEAR(readings.back().wy, -0.2, 1e-6);
  EXPECT_NEAR(readings.back().wz, -0.3, 1e-6);
}

TEST_F(XsensImuTest, GarbageBetweenMessagesIsSkippedAndGapsAreCounted) {
  XsensEmulator emulator(pty_);
  emulator.SetRate(0.0F, 0.0F, 0.5F);
  auto imu = OpenImu();
  ASSERT_NE(imu, nullptr);
  ASSERT_TRUE(WaitUntil([&] { return imu->Stats().samples > 2; }));
  auto corrupt = XsensEmulator::MtData2(7, {5.0F, 5.0F, 5.0F});
  corrupt[corrupt.size() / 2] ^= 0x10;
  emulator.InjectRaw({0xFA, 0xFA, 0xFF, 0x00, 0x13});
  emulator.InjectRaw(corrupt);
  emulator.InjectRaw({corrupt.begin(), corrupt.begin() + 9});
  emulator.SkipCounter(3);
  const std::uint64_t sent_before = emulator.samples_sent();
  ASSERT_TRUE(WaitUntil([&] { return emulator.samples_sent() > sent_before + 10; }));
  const auto readings = CollectUntil(*imu, [](const ImuReading&) { return true; });
  for (const ImuReading& r : readings) EXPECT_FLOAT_EQ(static_cast<float>(r.wz), 0.5F);
  const XsensLinkStats stats = imu->Stats();
  EXPECT_EQ(stats.lost_samples, 3U);
  EXPECT_GE(stats.checksum_errors, 1U);
  EXPECT_GT(stats.skipped_bytes, 0U);
}

TEST_F(XsensImuTest, FixedPointOutputIsAClearError) {
  XsensEmulator emulator(pty_);
  emulator.SetFixedPoint(true);
  auto imu = OpenImu();
  ASSERT_NE(imu, nullptr);
  Expected<std::vector<ImuReading>> result = std::vector<ImuReading>{};
  ASSERT_TRUE(WaitUntil([&] {
    result = imu->ReadImu();
    return !result.ok();
  }));
  EXPECT_NE(result.error().message.find("Float32"), std::string::npos);
}

TEST_F(XsensImuTest, SilenceIsAnErrorNamingTheDevice) {
  XsensEmulator emulator(pty_);
  emulator.SetSilent(true);
  auto imu = OpenImu();
  ASSERT_NE(imu, nullptr);
  Expected<std::vector<ImuReading>> result = std::vector<ImuReading>{};
  ASSERT_TRUE(WaitUntil([&] {
    result = imu->ReadImu();
    return !result.ok();
  }));
  EXPECT_NE(result.error().message.find(pty_.slave_path()), std::string::npos);
  EXPECT_NE(result.error().message.find("no rate-of-turn"), std::string::npos);
}

TEST_F(XsensImuTest, UnplugMidStreamDeliversWhatArrivedThenAnError) {
  auto emulator = std::make_unique<XsensEmulator>(pty_);
  auto imu = OpenImu();
  ASSERT_NE(imu, nullptr);
  ASSERT_TRUE(WaitUntil([&] { return imu->Stats().samples > 3; }));
  emulator->Unplug();
  emulator.reset();
  Expected<std::vector<ImuReading>> result = std::vector<ImuReading>{};
  std::size_t delivered = 0;
  ASSERT_TRUE(WaitUntil([&] {
    result = imu->ReadImu();
    if (result.ok()) delivered += result->size();
    return !result.ok();
  }));
  EXPECT_GT(delivered, 3U);
  EXPECT_NE(result.error().message.find("link lost"), std::string::npos);
}

}  // namespace
}  // namespace dynamap::robotio::hardware
