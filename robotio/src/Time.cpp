#include "dynamap/robotio/Time.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace dynamap::robotio {

std::int64_t SecondsToNanos(double seconds) {
  return static_cast<std::int64_t>(std::llround(seconds * 1e9));
}

std::string FormatStamp(std::int64_t ns) {
  const bool negative = ns < 0;
  const std::uint64_t magnitude =
      negative ? static_cast<std::uint64_t>(-(ns + 1)) + 1 : static_cast<std::uint64_t>(ns);
  char buffer[48];
  std::snprintf(buffer, sizeof(buffer), "%s%" PRIu64 ".%09" PRIu64, negative ? "-" : "",
                static_cast<std::uint64_t>(magnitude / 1'000'000'000U), static_cast<std::uint64_t>(magnitude % 1'000'000'000U));
  return buffer;
}

std::optional<std::int64_t> ParseStamp(const std::string& text) {
  if (text.empty()) return std::nullopt;
  std::size_t i = 0;
  bool negative = false;
  if (text[0] == '-' || text[0] == '+') {
    negative = text[0] == '-';
    i = 1;
  }
  std::int64_t whole = 0;
  std::size_t digits = 0;
  for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i, ++digits) {
    if (whole > 9'000'000'000LL) return std::nullopt;
    whole = whole * 10 + (text[i] - '0');
  }
  std::int64_t fraction = 0;
  int fraction_digits = 0;
  if (i < text.size() && text[i] == '.') {
    for (++i; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i) {
      if (fraction_digits < 9) {
        fraction = fraction * 10 + (text[i] - '0');
        ++fraction_digits;
      } else if (fraction_digits == 9 && text[i] >= '5') {
        // Round half up at the nanosecond.
        fraction += 1;
        fraction_digits = 10;
      } else if (fraction_digits == 9) {
        fraction_digits = 10;
      }
      ++digits;
    }
  }
  if (i != text.size() || digits == 0) return std::nullopt;
  for (int k = std::min(fraction_digits, 9); k < 9; ++k) fraction *= 10;
  const std::int64_t ns = whole * 1'000'000'000LL + fraction;
  return negative ? -ns : ns;
}

}  // namespace dynamap::robotio
