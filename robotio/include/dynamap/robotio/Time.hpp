// Timestamps: integer nanoseconds of one monotonic clock; files store seconds.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace dynamap::robotio {

constexpr std::int64_t kNanosPerSecond = 1'000'000'000;

[[nodiscard]] inline double NanosToSeconds(std::int64_t ns) {
  return static_cast<double>(ns) * 1e-9;
}
[[nodiscard]] std::int64_t SecondsToNanos(double seconds);
// Fixed-point seconds with 9 decimals (exact for integer ns), as TUM files store them.
[[nodiscard]] std::string FormatStamp(std::int64_t ns);
// Parses "1311868164.363181" style stamps exactly into ns (no floating point rounding).
[[nodiscard]] std::optional<std::int64_t> ParseStamp(const std::string& text);

}  // namespace dynamap::robotio
