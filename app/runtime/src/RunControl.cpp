#include "dynamap/app/runtime/RunControl.hpp"

namespace dynamap::app::runtime {

const char* ToString(MissionState state) {
  switch (state) {
    case MissionState::kIdle: return "idle";
    case MissionState::kRunning: return "running";
    case MissionState::kPaused: return "paused";
    case MissionState::kStopping: return "stopping";
    case MissionState::kFinished: return "finished";
  }
  return "unknown";
}

bool RunControl::Start() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (state_ != MissionState::kIdle) return false;
  state_ = MissionState::kRunning;
  changed_.notify_all();
  return true;
}

bool RunControl::Pause() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (state_ != MissionState::kRunning) return false;
  state_ = MissionState::kPaused;
  changed_.notify_all();
  return true;
}

bool RunControl::Resume() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (state_ != MissionState::kPaused) return false;
  state_ = MissionState::kRunning;
  changed_.notify_all();
  return true;
}

bool RunControl::Stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (state_ == MissionState::kStopping || state_ == MissionState::kFinished) return false;
  state_ = MissionState::kStopping;
  changed_.notify_all();
  return true;
}

void RunControl::MarkFinished() {
  std::lock_guard<std::mutex> lock(mutex_);
  state_ = MissionState::kFinished;
  changed_.notify_all();
}

MissionState RunControl::state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_;
}

bool RunControl::stopping() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_ == MissionState::kStopping || state_ == MissionState::kFinished;
}

bool RunControl::WaitWhilePaused() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return state_ != MissionState::kPaused; });
  return state_ == MissionState::kRunning || state_ == MissionState::kIdle;
}

bool RunControl::SleepFor(std::chrono::nanoseconds duration) {
  std::unique_lock<std::mutex> lock(mutex_);
  return !changed_.wait_for(lock, duration, [&] {
    return state_ == MissionState::kStopping || state_ == MissionState::kFinished;
  });
}

}  // namespace dynamap::app::runtime
