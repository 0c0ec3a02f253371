// Mission state shared by the runtime's threads: idle → running ⇄ paused → stopping →
// finished. Workers call WaitWhilePaused() at the top of each cycle, so pause takes effect
// within one cycle and stop wakes every sleeper.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>

namespace dynamap::app::runtime {

enum class MissionState { kIdle, kRunning, kPaused, kStopping, kFinished };

[[nodiscard]] const char* ToString(MissionState state);

class RunControl {
 public:
  // Each returns false (and changes nothing) when the transition is not allowed from the
  // current state, e.g. Resume() while running.
  bool Start();
  bool Pause();
  bool Resume();
  bool Stop();
  void MarkFinished();

  [[nodiscard]] MissionState state() const;
  [[nodiscard]] bool stopping() const;  // Stopping or finished: workers should leave.

  // Blocks while paused; returns false once the mission is stopping.
  bool WaitWhilePaused();
  // Sleeps up to `duration`, returning early (false) when the mission stops.
  bool SleepFor(std::chrono::nanoseconds duration);

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  MissionState state_ = MissionState::kIdle;
};

}  // namespace dynamap::app::runtime
