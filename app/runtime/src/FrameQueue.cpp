#include "dynamap/app/runtime/FrameQueue.hpp"

#include <algorithm>

namespace dynamap::app::runtime {

void FrameQueue::Push(CapturedFrame frame) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ++delivered_;
    auto [it, inserted] = pending_.try_emplace(frame.depth.sensor_id, std::move(frame));
    if (!inserted) {
      ++dropped_;
      it->second = std::move(frame);
    }
  }
  arrived_.notify_one();
}

std::vector<CapturedFrame> FrameQueue::TakeAll(std::chrono::milliseconds timeout) {
  std::unique_lock<std::mutex> lock(mutex_);
  arrived_.wait_for(lock, timeout, [&] { return closed_ || !pending_.empty(); });
  std::vector<CapturedFrame> frames;
  for (auto& [sensor, frame] : pending_) frames.push_back(std::move(frame));
  pending_.clear();
  std::sort(frames.begin(), frames.end(),
            [](const auto& a, const auto& b) { return a.depth.stamp_ns < b.depth.stamp_ns; });
  return frames;
}

void FrameQueue::Close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closed_ = true;
  }
  arrived_.notify_all();
}

std::int64_t FrameQueue::delivered() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return delivered_;
}

std::int64_t FrameQueue::dropped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return dropped_;
}

}  // namespace dynamap::app::runtime
