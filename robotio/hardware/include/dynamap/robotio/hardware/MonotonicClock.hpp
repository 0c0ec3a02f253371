// The host clock every hardware driver stamps with: integer nanoseconds of the monotonic
// clock (DESIGN.md, "Frames, units, time"), so drivers' stamps compare directly.
#pragma once

#include <chrono>
#include <cstdint>

namespace dynamap::robotio::hardware {

[[nodiscard]] inline std::int64_t MonotonicNanos() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace dynamap::robotio::hardware
