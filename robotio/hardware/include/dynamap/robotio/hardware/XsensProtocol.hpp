// The Xsens MT binary protocol as MTi gyros speak it over serial (docs/HARDWARE.md, "IMU"):
// message framing with its checksum, a byte-stream parser, and the MTData2 fields the
// gyro driver reads (rate of turn, packet counter, fine sample time).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace dynamap::robotio::hardware {

constexpr std::uint8_t kXsensPreamble = 0xFA;
constexpr std::uint8_t kXsensBusId = 0xFF;          // "Master device" bus identifier.
constexpr std::uint8_t kXsensGoToMeasurement = 0x10;
constexpr std::uint8_t kXsensGoToMeasurementAck = 0x11;
constexpr std::uint8_t kXsensError = 0x42;
constexpr std::uint8_t kXsensMtData2 = 0x36;
constexpr std::uint16_t kXsensPacketCounter = 0x1020;   // uint16.
constexpr std::uint16_t kXsensSampleTimeFine = 0x1060;  // uint32, 10 kHz ticks.
constexpr std::uint16_t kXsensRateOfTurn = 0x8020;      // 3 values, rad/s, sensor frame.

struct XsensMessage {
  std::uint8_t mid = 0;             // Message identifier.
  std::vector<std::uint8_t> data;   // Payload (up to 2047 bytes with extended length).
};

// FA FF MID LEN [LENH LENL] DATA CS, where the checksum makes the sum of every byte after
// the preamble zero modulo 256; lengths ≥ 255 use the extended form (LEN = 0xFF).
[[nodiscard]] std::vector<std::uint8_t> EncodeXsensMessage(const XsensMessage& message);

class XsensFrameParser {
 public:
  struct Counters {
    std::uint64_t messages = 0;         // Messages with a valid checksum.
    std::uint64_t checksum_errors = 0;  // Candidates whose checksum failed.
    std::uint64_t skipped_bytes = 0;    // Bytes dropped while searching for a preamble.
  };

  // Appends `bytes` and returns every complete message with a valid checksum.
  [[nodiscard]] std::vector<XsensMessage> Feed(const std::vector<std::uint8_t>& bytes);
  [[nodiscard]] const Counters& counters() const { return counters_; }

 private:
  std::vector<std::uint8_t> buffer_;
  Counters counters_;
};

struct XsensSample {
  std::optional<std::array<double, 3>> rate_of_turn;  // rad/s, sensor frame.
  std::optional<std::uint16_t> packet_counter;
  std::optional<std::uint32_t> sample_time_fine;      // 10 kHz ticks.
};

// Decodes an MTData2 payload: either the sample, or a message that says what is wrong
// (truncated packet, rate of turn in a fixed-point format the driver does not read).
struct XsensDecodeResult {
  XsensSample sample;
  std::optional<std::string> problem;
};
[[nodiscard]] XsensDecodeResult DecodeXsensMtData2(const std::vector<std::uint8_t>& payload);

}  // namespace dynamap::robotio::hardware
