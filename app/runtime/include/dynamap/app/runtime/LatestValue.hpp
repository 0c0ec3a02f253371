// A mediator slot (thesis 2.2): the newest value of one kind of data, written by one
// thread and read by any. Readers copy out under a short lock and never wait on the
// writer's work; a version number tells them whether anything new arrived.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <optional>
#include <utility>

namespace dynamap::app::runtime {

template <typename T>
class LatestValue {
 public:
  struct Versioned {
    T value;
    std::uint64_t version = 0;  // 1 for the first value ever set.
  };

  void Set(T value) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      value_ = std::move(value);
      ++version_;
    }
    changed_.notify_all();
  }

  [[nodiscard]] std::optional<Versioned> Get() const {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!value_) return std::nullopt;
    return Versioned{*value_, version_};
  }

  [[nodiscard]] std::uint64_t version() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return version_;
  }

  // Waits until a value newer than `seen_version` is there, or `timeout` passes.
  [[nodiscard]] std::optional<Versioned> WaitNewer(std::uint64_t seen_version,
                                                   std::chrono::milliseconds timeout) const {
    std::unique_lock<std::mutex> lock(mutex_);
    if (!changed_.wait_for(lock, timeout, [&] { return version_ > seen_version && value_; })) {
      return std::nullopt;
    }
    return Versioned{*value_, version_};
  }

  // Wakes every waiter (used on shutdown so no thread sleeps through a stop).
  void WakeAll() const { changed_.notify_all(); }

 private:
  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::optional<T> value_;
  std::uint64_t version_ = 0;
};

}  // namespace dynamap::app::runtime
