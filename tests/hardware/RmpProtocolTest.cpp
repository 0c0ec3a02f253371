#include <gtest/gtest.h>

#include "RmpEmulator.hpp"
#include "dynamap/robotio/hardware/RmpProtocol.hpp"

namespace dynamap::robotio::hardware {
namespace {

TEST(RmpProtocol, StopCommandFrameMatchesHandComputedBytes) {
  const auto frame = EncodeRmpCommandFrame(MakeRmpMotionCommand(0, 0));
  // F0+55+04+13 = 0x15C → folded 0x5D → two's complement 0xA3.
  const std::array<std::uint8_t, 18> expected = {0xF0, 0x55, 0, 0, 0, 0, 0x04, 0x13, 0,
                                                 0,    0,    0, 0, 0, 0, 0,    0,    0xA3};
  EXPECT_EQ(frame, expected);
}

TEST(RmpProtocol, MotionCommandIsClampedToTheBaseRange) {
  const RmpCanMessage message = MakeRmpMotionCommand(5000, -5000);
  EXPECT_EQ(static_cast<std::int16_t>(message.data[0] << 8 | message.data[1]), 1176);
  EXPECT_EQ(static_cast<std::int16_t>(message.data[2] << 8 | message.data[3]), -1024);
}

TEST(RmpProtocol, ParserReassemblesFramesSplitAnywhereAndSkipsNoise) {
  std::vector<std::uint8_t> stream = {0x00, 0xF0, 0x13, 0x37};
  const auto a = test::RmpEmulator::WheelFrame(123456, -42);
  const auto b = test::RmpEmulator::WheelFrame(-7, 99);
  stream.insert(stream.end(), a.begin(), a.end());
  stream.insert(stream.end(), {0xF0, 0xF0, 0x55});
  stream.insert(stream.end(), b.begin(), b.end());
  RmpFrameParser parser;
  std::vector<RmpCanMessage> messages;
  for (std::uint8_t byte : stream) {
    for (const auto& m : parser.Feed({byte})) messages.push_back(m);
  }
  ASSERT_EQ(messages.size(), 2U);
  EXPECT_EQ(messages[0].id, 0x0403);
  EXPECT_EQ(*DecodeRmpStatus(messages[0]).left_wheel_counts, 123456);
  EXPECT_EQ(*DecodeRmpStatus(messages[0]).right_wheel_counts, -42);
  EXPECT_EQ(*DecodeRmpStatus(messages[1]).left_wheel_counts, -7);
  EXPECT_EQ(*DecodeRmpStatus(messages[1]).right_wheel_counts, 99);
  EXPECT_GT(parser.counters().skipped_bytes, 0U);
}

TEST(RmpProtocol, ParserRejectsBadChecksumAndRecoversOnTheNextFrame) {
  std::vector<std::uint8_t> stream = test::RmpEmulator::WheelFrame(1, 1, /*corrupt=*/true);
  const auto good = test::RmpEmulator::WheelFrame(2, 3);
  stream.insert(stream.end(), good.begin(), good.end());
  RmpFrameParser parser;
  const auto messages = parser.Feed(stream);
  ASSERT_EQ(messages.size(), 1U);
  EXPECT_EQ(*DecodeRmpStatus(messages[0]).left_wheel_counts, 2);
  EXPECT_GE(parser.counters().checksum_errors, 1U);
}

TEST(RmpProtocol, TruncatedFrameFollowedByAWholeOneLosesOnlyTheTruncatedOne) {
  std::vector<std::uint8_t> stream = test::RmpEmulator::WheelFrame(5, 5);
  stream.resize(11);
  const auto good = test::RmpEmulator::WheelFrame(6, 7);
  stream.insert(stream.end(), good.begin(), good.end());
  RmpFrameParser parser;
  const auto messages = parser.Feed(stream);
  ASSERT_EQ(messages.size(), 1U);
  EXPECT_EQ(*DecodeRmpStatus(messages[0]).right_wheel_counts, 7);
}

TEST(RmpProtocol, StatusDecodesBatteryModeAndCommandEcho) {
  const std::uint8_t mode[8] = {0, 2, 0, 0, 0, 0, 0x01, 0x20};
  RmpFrameParser parser;
  const auto messages = parser.Feed(test::RmpEmulator::StatusFrame(0x0406, mode));
  ASSERT_EQ(messages.size(), 1U);
  const RmpStatus status = DecodeRmpStatus(messages[0]);
  EXPECT_EQ(*status.operational_mode, 2);
  EXPECT_DOUBLE_EQ(*status.powerbase_battery_v, 72.0);
  const std::uint8_t echo[8] = {0xFF, 0x38, 0x00, 0x10, 0, 0, 0, 0};
  const RmpStatus e = DecodeRmpStatus(parser.Feed(test::RmpEmulator::StatusFrame(0x0407, echo))[0]);
  EXPECT_EQ(*e.velocity_command_echo, -200);
  EXPECT_EQ(*e.turn_command_echo, 16);
}

}  // namespace
}  // namespace dynamap::robotio::hardware
