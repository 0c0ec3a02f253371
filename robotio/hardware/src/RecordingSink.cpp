#include "RecordingSink.hpp"

#include <algorithm>
#include <utility>

namespace dynamap::robotio::hardware::internal {

RecordingSink::RecordingSink(RecordingWriter& writer, int cameras, int max_queued_frames)
    : writer_(writer),
      max_queued_frames_(static_cast<std::size_t>(std::max(1, max_queued_frames))),
      thread_([this] { Run(); }) {
  std::lock_guard<std::mutex> lock(mutex_);
  counts_.frames.assign(static_cast<std::size_t>(std::max(0, cameras)), 0);
}

RecordingSink::~RecordingSink() { (void)Close(); }

void RecordingSink::AddOdometry(std::vector<OdometryReading> readings) {
  if (!readings.empty()) Push(std::move(readings));
}

void RecordingSink::AddImu(std::vector<ImuReading> readings) {
  if (!readings.empty()) Push(std::move(readings));
}

void RecordingSink::AddFrame(DepthFrame frame) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (queued_frames_ >= max_queued_frames_) {
      ++counts_.dropped_frames;
      return;
    }
    ++queued_frames_;
  }
  Push(std::move(frame));
}

void RecordingSink::Push(Item item) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (closing_ || error_) {
    if (std::holds_alternative<DepthFrame>(item)) --queued_frames_;
    return;
  }
  queue_.push_back(std::move(item));
  ready_.notify_one();
}

std::optional<Error> RecordingSink::error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

SinkCounts RecordingSink::counts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counts_;
}

std::optional<Error> RecordingSink::Close() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
    ready_.notify_one();
  }
  if (thread_.joinable()) thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

void RecordingSink::Run() {
  for (;;) {
    Item item;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      ready_.wait(lock, [this] { return !queue_.empty() || closing_; });
      // Closing still writes what was queued: nothing received is lost on a clean stop.
      if (queue_.empty()) return;
      item = std::move(queue_.front());
      queue_.pop_front();
    }
    const Status written = Write(item);
    std::lock_guard<std::mutex> lock(mutex_);
    if (const auto* frame = std::get_if<DepthFrame>(&item)) {
      --queued_frames_;
      if (written.ok()) {
        const auto sensor = static_cast<std::size_t>(frame->sensor_id);
        if (counts_.frames.size() <= sensor) counts_.frames.resize(sensor + 1, 0);
        ++counts_.frames[sensor];
      }
    } else if (const auto* odometry = std::get_if<std::vector<OdometryReading>>(&item)) {
      if (written.ok()) counts_.odometry += odometry->size();
    } else if (const auto* imu = std::get_if<std::vector<ImuReading>>(&item)) {
      if (written.ok()) counts_.imu += imu->size();
    }
    if (!written.ok()) {
      error_ = written.error();
      queue_.clear();
      queued_frames_ = 0;
      return;
    }
  }
}

Status RecordingSink::Write(const Item& item) {
  if (const auto* frame = std::get_if<DepthFrame>(&item)) return writer_.AddDepth(*frame);
  if (const auto* odometry = std::get_if<std::vector<OdometryReading>>(&item)) {
    for (const OdometryReading& r : *odometry) {
      if (Status s = writer_.AddOdometry(r); !s) return s;
    }
    return Ok{};
  }
  for (const ImuReading& r : std::get<std::vector<ImuReading>>(item)) {
    if (Status s = writer_.AddImu(r); !s) return s;
  }
  return Ok{};
}

}  // namespace dynamap::robotio::hardware::internal
