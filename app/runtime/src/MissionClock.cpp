#include "dynamap/app/runtime/MissionClock.hpp"

#include <thread>

namespace dynamap::app::runtime {

MissionClock::MissionClock(double speed) : speed_(speed) {}

void MissionClock::AdvanceTo(std::int64_t now_ns) {
  if (!paced()) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      now_ns_ = now_ns;
    }
    advanced_.notify_all();
    return;
  }
  std::chrono::steady_clock::time_point due;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    now_ns_ = now_ns;
    if (!anchored_) {
      anchored_ = true;
      anchor_sim_ns_ = now_ns;
      anchor_wall_ = std::chrono::steady_clock::now();
    }
    const double wall_ns = static_cast<double>(now_ns - anchor_sim_ns_) / speed_;
    due = anchor_wall_ + std::chrono::nanoseconds(static_cast<std::int64_t>(wall_ns));
  }
  advanced_.notify_all();
  std::this_thread::sleep_until(due);
}

void MissionClock::Reanchor() {
  std::lock_guard<std::mutex> lock(mutex_);
  anchored_ = false;
}

std::int64_t MissionClock::now_ns() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return now_ns_;
}

bool MissionClock::WaitUntil(std::int64_t target_ns, const RunControl& control) const {
  std::unique_lock<std::mutex> lock(mutex_);
  while (now_ns_ < target_ns) {
    if (control.stopping()) return false;
    // Bounded wait: a stop is noticed within 50 ms even if nobody advances the clock.
    advanced_.wait_for(lock, std::chrono::milliseconds(50));
  }
  return !control.stopping();
}

}  // namespace dynamap::app::runtime
