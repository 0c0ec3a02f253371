// The Segway RMP 50/100/200 USB message protocol (docs/HARDWARE.md, "Segway RMP"): 18-byte
// USB frames that carry one CAN message each, their checksum, and the meaning of the
// command and status messages the driver uses. Pure functions and a byte-stream parser.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace dynamap::robotio::hardware {

constexpr std::size_t kRmpFrameSize = 18;
constexpr std::uint8_t kRmpFrameStart = 0xF0;    // Byte 0 of every USB frame.
constexpr std::uint8_t kRmpCanMessage = 0x55;    // Byte 1: the frame carries a CAN message.
constexpr std::uint16_t kRmpMotionCommandId = 0x0413;  // Host → RMP: velocity and turn.
constexpr std::uint16_t kRmpStatusFirstId = 0x0400;    // RMP → host status block 0x400-0x407.
constexpr std::uint16_t kRmpStatusLastId = 0x0407;
constexpr int kRmpMaxVelocityCounts = 1176;  // Velocity command range ±1176 counts.
constexpr int kRmpMaxTurnCounts = 1024;      // Turn command range ±1024 counts.

struct RmpCanMessage {
  std::uint16_t id = 0;                   // 11-bit CAN identifier.
  std::array<std::uint8_t, 8> data{};     // Payload, big-endian 16-bit words.
};

// Two's complement of the 16-bit sum of bytes 0..16 folded twice to 8 bits; a frame is
// valid when RmpChecksum(frame) equals frame[17].
[[nodiscard]] std::uint8_t RmpChecksum(const std::uint8_t* frame);

// Host → RMP frame: F0 55 00 00 00 00 idH idL 00 d0..d7 cs.
[[nodiscard]] std::array<std::uint8_t, kRmpFrameSize> EncodeRmpCommandFrame(
    const RmpCanMessage& message);
// The motion command (CAN id 0x413): velocity and turn counts, clamped to their ranges,
// with no configuration command.
[[nodiscard]] RmpCanMessage MakeRmpMotionCommand(int velocity_counts, int turn_counts);

// Reassembles RMP → host frames (F0 55 ch 00 id>>3 (id&7)<<5 00 00 00 d0..d7 cs) from a
// byte stream that may split frames anywhere, lose bytes or carry noise.
class RmpFrameParser {
 public:
  struct Counters {
    std::uint64_t frames = 0;           // Frames with a valid checksum.
    std::uint64_t checksum_errors = 0;  // Candidate frames whose checksum failed.
    std::uint64_t skipped_bytes = 0;    // Bytes dropped while searching for a frame start.
  };

  // Appends `bytes` and returns the CAN messages of every complete, valid frame.
  [[nodiscard]] std::vector<RmpCanMessage> Feed(const std::vector<std::uint8_t>& bytes);
  [[nodiscard]] const Counters& counters() const { return counters_; }

 private:
  std::vector<std::uint8_t> buffer_;
  Counters counters_;
};

// Decoded status words. Counts stay raw here; the driver converts them with its config.
struct RmpStatus {
  std::optional<std::int32_t> left_wheel_counts;   // 0x403: integrated left wheel travel.
  std::optional<std::int32_t> right_wheel_counts;  // 0x403: integrated right wheel travel.
  std::optional<std::uint16_t> servo_frames;       // 0x402: 100 Hz frame counter.
  std::optional<std::uint16_t> operational_mode;   // 0x406: 0 disabled, 1 tractor, 2 balance.
  std::optional<double> powerbase_battery_v;       // 0x406: V.
  std::optional<std::int16_t> velocity_command_echo;  // 0x407: counts the base executes.
  std::optional<std::int16_t> turn_command_echo;      // 0x407: counts the base executes.
};

// What `message` says about the base; fields it does not carry stay empty.
[[nodiscard]] RmpStatus DecodeRmpStatus(const RmpCanMessage& message);

}  // namespace dynamap::robotio::hardware
