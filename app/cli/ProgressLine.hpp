// A single self-overwriting progress line on stderr for long CLI work
// ("recording  42.0 s / 60.0 s  [#######.....]  70%  1.8x real time").
#pragma once

#include <chrono>
#include <string>

namespace dynamap::app {

class ProgressLine {
 public:
  explicit ProgressLine(std::string label);
  // fraction in [0, 1]; `detail` is printed after the bar. Redraws at most 10 times/s.
  void Update(double fraction, const std::string& detail);
  // Draws the final state and ends the line.
  void Finish(const std::string& detail);

 private:
  void Draw(double fraction, const std::string& detail);

  std::string label_;
  std::chrono::steady_clock::time_point last_draw_{};
  bool drawn_ = false;
  bool is_terminal_ = false;
};

}  // namespace dynamap::app
