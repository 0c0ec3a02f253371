// The disk side of a hardware recording: a thread that appends readings and depth frames
// to a RecordingWriter, so PNG encoding never delays the control loop or a camera thread.
// Readings are never dropped; depth frames are, when the disk falls behind by more than a
// bounded queue (counted, so the report says so).
#pragma once

#include <condition_variable>
#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <thread>
#include <variant>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"

namespace dynamap::robotio::hardware::internal {

struct SinkCounts {
  std::uint64_t odometry = 0;         // Odometry readings written.
  std::uint64_t imu = 0;              // Gyro readings written.
  std::vector<std::uint64_t> frames;  // Depth frames written, per sensor id.
  std::uint64_t dropped_frames = 0;   // Depth frames dropped because the disk lagged.
};

class RecordingSink {
 public:
  RecordingSink(RecordingWriter& writer, int cameras, int max_queued_frames);
  ~RecordingSink();
  RecordingSink(const RecordingSink&) = delete;
  RecordingSink& operator=(const RecordingSink&) = delete;

  void AddOdometry(std::vector<OdometryReading> readings);
  void AddImu(std::vector<ImuReading> readings);
  // Queues the frame unless too many are waiting already (then it is dropped and counted).
  void AddFrame(DepthFrame frame);

  // The first write error, if one happened; nothing is written after it.
  [[nodiscard]] std::optional<Error> error() const;
  [[nodiscard]] SinkCounts counts() const;
  // Writes everything still queued and ends the thread; returns the first write error.
  std::optional<Error> Close();

 private:
  using Item = std::variant<std::vector<OdometryReading>, std::vector<ImuReading>, DepthFrame>;
  void Push(Item item);
  void Run();
  [[nodiscard]] Status Write(const Item& item);

  RecordingWriter& writer_;
  const std::size_t max_queued_frames_;

  mutable std::mutex mutex_;  // Guards everything below.
  std::condition_variable ready_;
  std::deque<Item> queue_;
  std::size_t queued_frames_ = 0;
  SinkCounts counts_;
  std::optional<Error> error_;
  bool closing_ = false;

  std::thread thread_;  // Last: starts once the members above exist.
};

}  // namespace dynamap::robotio::hardware::internal
