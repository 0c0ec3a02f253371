#include "dynamap/robotio/hardware/RmpProtocol.hpp"

#include <algorithm>

namespace dynamap::robotio::hardware {
namespace {

std::int16_t Int16At(const std::array<std::uint8_t, 8>& data, int i) {
  return static_cast<std::int16_t>(static_cast<std::uint16_t>(data[i] << 8 | data[i + 1]));
}
std::uint16_t Uint16At(const std::array<std::uint8_t, 8>& data, int i) {
  return static_cast<std::uint16_t>(data[i] << 8 | data[i + 1]);
}
// 32-bit status values are sent as two 16-bit words, low word first.
std::int32_t Int32At(const std::array<std::uint8_t, 8>& data, int i) {
  const std::uint32_t low = Uint16At(data, i);
  const std::uint32_t high = Uint16At(data, i + 2);
  return static_cast<std::int32_t>(high << 16 | low);
}

}  // namespace

std::uint8_t RmpChecksum(const std::uint8_t* frame) {
  std::uint16_t sum = 0;
  for (std::size_t i = 0; i + 1 < kRmpFrameSize; ++i) sum = static_cast<std::uint16_t>(sum + frame[i]);
  for (int fold = 0; fold < 2; ++fold) sum = static_cast<std::uint16_t>((sum & 0xFF) + (sum >> 8));
  return static_cast<std::uint8_t>((~sum + 1) & 0xFF);
}

std::array<std::uint8_t, kRmpFrameSize> EncodeRmpCommandFrame(const RmpCanMessage& message) {
  std::array<std::uint8_t, kRmpFrameSize> frame{};
  frame[0] = kRmpFrameStart;
  frame[1] = kRmpCanMessage;
  frame[6] = static_cast<std::uint8_t>(message.id >> 8);
  frame[7] = static_cast<std::uint8_t>(message.id & 0xFF);
  std::copy(message.data.begin(), message.data.end(), frame.begin() + 9);
  frame[17] = RmpChecksum(frame.data());
  return frame;
}

RmpCanMessage MakeRmpMotionCommand(int velocity_counts, int turn_counts) {
  const auto v = static_cast<std::int16_t>(
      std::clamp(velocity_counts, -kRmpMaxVelocityCounts, kRmpMaxVelocityCounts));
  const auto t =
      static_cast<std::int16_t>(std::clamp(turn_counts, -kRmpMaxTurnCounts, kRmpMaxTurnCounts));
  RmpCanMessage message;
  message.id = kRmpMotionCommandId;
  message.data[0] = static_cast<std::uint8_t>(static_cast<std::uint16_t>(v) >> 8);
  message.data[1] = static_cast<std::uint8_t>(static_cast<std::uint16_t>(v) & 0xFF);
  message.data[2] = static_cast<std::uint8_t>(static_cast<std::uint16_t>(t) >> 8);
  message.data[3] = static_cast<std::uint8_t>(static_cast<std::uint16_t>(t) & 0xFF);
  // Bytes 4..7: configuration command and parameter, 0 = none.
  return message;
}

std::vector<RmpCanMessage> RmpFrameParser::Feed(const std::vector<std::uint8_t>& bytes) {
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  std::vector<RmpCanMessage> messages;
  std::size_t pos = 0;
  while (true) {
    const auto start = std::find(buffer_.begin() + static_cast<std::ptrdiff_t>(pos),
                                 buffer_.end(), kRmpFrameStart);
    const auto start_index = static_cast<std::size_t>(start - buffer_.begin());
    counters_.skipped_bytes += start_index - pos;
    pos = start_index;
    if (buffer_.size() - pos < kRmpFrameSize) break;
    const std::uint8_t* frame = buffer_.data() + pos;
    if (RmpChecksum(frame) != frame[17]) {
      // Not a frame after all (noise, or a frame cut by lost bytes): resynchronise on the
      // next start byte instead of dropping a whole frame's worth of bytes.
      ++counters_.checksum_errors;
      ++counters_.skipped_bytes;
      ++pos;
      continue;
    }
    ++counters_.frames;
    if (frame[1] == kRmpCanMessage) {
      RmpCanMessage message;
      message.id = static_cast<std::uint16_t>(frame[4] << 3 | frame[5] >> 5);
      std::copy(frame + 9, frame + 17, message.data.begin());
      messages.push_back(message);
    }
    pos += kRmpFrameSize;
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(pos));
  return messages;
}

RmpStatus DecodeRmpStatus(const RmpCanMessage& message) {
  RmpStatus status;
  const auto& d = message.data;
  switch (message.id) {
    case 0x0402:
      status.servo_frames = Uint16At(d, 6);
      break;
    case 0x0403:
      status.left_wheel_counts = Int32At(d, 0);
      status.right_wheel_counts = Int32At(d, 4);
      break;
    case 0x0406:
      status.operational_mode = Uint16At(d, 0);
      status.powerbase_battery_v = Uint16At(d, 6) / 4.0;
      break;
    case 0x0407:
      status.velocity_command_echo = Int16At(d, 0);
      status.turn_command_echo = Int16At(d, 2);
      break;
    default:
      break;
  }
  return status;
}

}  // namespace dynamap::robotio::hardware
