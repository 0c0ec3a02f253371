#include "cli/ProgressLine.hpp"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace dynamap::app {

ProgressLine::ProgressLine(std::string label)
    : label_(std::move(label)), is_terminal_(::isatty(STDERR_FILENO) != 0) {}

void ProgressLine::Update(double fraction, const std::string& detail) {
  const auto now = std::chrono::steady_clock::now();
  // Not a terminal (CI logs): a line every 5 s instead of redrawing 10 times a second.
  const auto period = is_terminal_ ? std::chrono::milliseconds(100) : std::chrono::seconds(5);
  if (drawn_ && now - last_draw_ < period) return;
  last_draw_ = now;
  Draw(fraction, detail);
}

void ProgressLine::Finish(const std::string& detail) {
  Draw(1.0, detail);
  if (is_terminal_) std::fputc('\n', stderr);
}

void ProgressLine::Draw(double fraction, const std::string& detail) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  constexpr int kWidth = 24;
  const int filled = static_cast<int>(fraction * kWidth + 0.5);
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(kWidth - filled), '.');
  std::fprintf(stderr, "%s%-12s [%s] %3d%%  %s%s", is_terminal_ ? "\r\033[K" : "", label_.c_str(),
               bar.c_str(), static_cast<int>(fraction * 100.0 + 0.5), detail.c_str(),
               is_terminal_ ? "" : "\n");
  std::fflush(stderr);
  drawn_ = true;
}

}  // namespace dynamap::app
