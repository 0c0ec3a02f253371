// Simulated mission time. The thread that steps the simulator advances it and is paced so
// that simulated time runs `speed` times faster than the wall clock; every other worker
// waits on it, so control at "50 Hz" means 50 Hz of simulated time at any speed.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>

#include "dynamap/app/runtime/RunControl.hpp"

namespace dynamap::app::runtime {

class MissionClock {
 public:
  // speed: simulated seconds per wall second; <= 0 does not pace at all (the driver then
  // waits for its consumers instead, see SimulationDriver).
  explicit MissionClock(double speed);

  // Sets simulated time to `now_ns` (monotonic), then sleeps as needed to keep pace.
  void AdvanceTo(std::int64_t now_ns);
  // Forgets the pacing anchor (after a pause, so the clock does not race to catch up).
  void Reanchor();
  [[nodiscard]] std::int64_t now_ns() const;
  [[nodiscard]] double speed() const { return speed_; }
  [[nodiscard]] bool paced() const { return speed_ > 0.0; }

  // Blocks until simulated time reaches `target_ns`; false when the mission stops first.
  bool WaitUntil(std::int64_t target_ns, const RunControl& control) const;
  // Wakes waiters so they can see a stop.
  void WakeAll() const { advanced_.notify_all(); }

 private:
  double speed_;
  mutable std::mutex mutex_;
  mutable std::condition_variable advanced_;
  std::int64_t now_ns_ = 0;
  bool anchored_ = false;
  std::int64_t anchor_sim_ns_ = 0;
  std::chrono::steady_clock::time_point anchor_wall_{};
};

}  // namespace dynamap::app::runtime
