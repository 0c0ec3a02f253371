#include "dynamap/robotio/hardware/XsensProtocol.hpp"

#include <algorithm>
#include <cstring>

namespace dynamap::robotio::hardware {
namespace {

constexpr std::size_t kMaxPayload = 2047;

std::uint32_t BigEndian32(const std::uint8_t* p) {
  return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | p[3];
}
std::uint64_t BigEndian64(const std::uint8_t* p) {
  return std::uint64_t{BigEndian32(p)} << 32 | BigEndian32(p + 4);
}
double Float32At(const std::uint8_t* p) {
  const std::uint32_t bits = BigEndian32(p);
  float value = 0.0F;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}
std::string Hex(std::uint16_t value) {
  static const char* kDigits = "0123456789ABCDEF";
  std::string text = "0x";
  for (int shift = 12; shift >= 0; shift -= 4) text += kDigits[(value >> shift) & 0xF];
  return text;
}
double Float64At(const std::uint8_t* p) {
  const std::uint64_t bits = BigEndian64(p);
  double value = 0.0;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace

std::vector<std::uint8_t> EncodeXsensMessage(const XsensMessage& message) {
  std::vector<std::uint8_t> bytes = {kXsensPreamble, kXsensBusId, message.mid};
  const std::size_t size = message.data.size();
  if (size < 0xFF) {
    bytes.push_back(static_cast<std::uint8_t>(size));
  } else {
    bytes.push_back(0xFF);
    bytes.push_back(static_cast<std::uint8_t>(size >> 8));
    bytes.push_back(static_cast<std::uint8_t>(size & 0xFF));
  }
  bytes.insert(bytes.end(), message.data.begin(), message.data.end());
  std::uint8_t sum = 0;
  for (std::size_t i = 1; i < bytes.size(); ++i) sum = static_cast<std::uint8_t>(sum + bytes[i]);
  bytes.push_back(static_cast<std::uint8_t>(-sum & 0xFF));
  return bytes;
}

std::vector<XsensMessage> XsensFrameParser::Feed(const std::vector<std::uint8_t>& bytes) {
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  std::vector<XsensMessage> messages;
  std::size_t pos = 0;
  while (true) {
    const auto start =
        std::find(buffer_.begin() + static_cast<std::ptrdiff_t>(pos), buffer_.end(), kXsensPreamble);
    const auto start_index = static_cast<std::size_t>(start - buffer_.begin());
    counters_.skipped_bytes += start_index - pos;
    pos = start_index;
    const std::size_t available = buffer_.size() - pos;
    if (available < 4) break;
    const std::uint8_t* m = buffer_.data() + pos;
    std::size_t header = 4;
    std::size_t length = m[3];
    if (m[3] == 0xFF) {
      if (available < 6) break;
      header = 6;
      length = std::size_t{m[4]} << 8 | m[5];
    }
    if (m[1] != kXsensBusId || length > kMaxPayload) {
      // A preamble byte inside noise or data: not a message start.
      ++counters_.skipped_bytes;
      ++pos;
      continue;
    }
    if (available < header + length + 1) break;
    std::uint8_t sum = 0;
    for (std::size_t i = 1; i < header + length + 1; ++i) sum = static_cast<std::uint8_t>(sum + m[i]);
    if (sum != 0) {
      ++counters_.checksum_errors;
      ++counters_.skipped_bytes;
      ++pos;
      continue;
    }
    ++counters_.messages;
    messages.push_back(XsensMessage{m[2], std::vector<std::uint8_t>(m + header, m + header + length)});
    pos += header + length + 1;
  }
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(pos));
  return messages;
}

XsensDecodeResult DecodeXsensMtData2(const std::vector<std::uint8_t>& payload) {
  XsensDecodeResult result;
  std::size_t pos = 0;
  while (pos < payload.size()) {
    if (payload.size() - pos < 3) {
      result.problem = "MTData2 packet header truncated at byte " + std::to_string(pos);
      return result;
    }
    const auto id = static_cast<std::uint16_t>(payload[pos] << 8 | payload[pos + 1]);
    const std::size_t size = payload[pos + 2];
    const std::uint8_t* data = payload.data() + pos + 3;
    if (payload.size() - pos - 3 < size) {
      result.problem = "MTData2 packet " + Hex(id) + " truncated";
      return result;
    }
    // The low two bits of a data identifier select the number format; the next two the
    // coordinate system (which does not apply to the sensor-frame rate of turn).
    const std::uint16_t type = id & 0xFFF0;
    const int format = id & 0x3;
    if (type == kXsensRateOfTurn) {
      if (format == 0 && size == 12) {
        result.sample.rate_of_turn = {Float32At(data), Float32At(data + 4), Float32At(data + 8)};
      } else if (format == 3 && size == 24) {
        result.sample.rate_of_turn = {Float64At(data), Float64At(data + 8), Float64At(data + 16)};
      } else {
        result.problem = "rate of turn in a format other than Float32/Float64 (configure the "
                         "MTi output as Float32)";
        return result;
      }
    } else if (id == kXsensPacketCounter && size == 2) {
      result.sample.packet_counter = static_cast<std::uint16_t>(data[0] << 8 | data[1]);
    } else if (id == kXsensSampleTimeFine && size == 4) {
      result.sample.sample_time_fine = BigEndian32(data);
    }
    pos += 3 + size;
  }
  return result;
}

}  // namespace dynamap::robotio::hardware
