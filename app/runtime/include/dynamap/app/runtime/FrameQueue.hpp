// Depth frames waiting for the SLAM thread. When SLAM falls behind, only the newest frame
// of each Kinect is kept and the ones it replaces are counted as dropped (thesis 2.3, run
// mode: "scans are only processed as fast as the mapping thread is able to").
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::app::runtime {

// A depth frame as it reaches the runtime, with the simulator's ground-truth labels when
// there are any (for the static/dynamic accuracy of the run).
struct CapturedFrame {
  robotio::DepthFrame depth;
  std::optional<robotio::LabelFrame> labels;
  std::optional<robotio::Pose2D> true_pose;  // T_map_base at capture, when simulated.
};

class FrameQueue {
 public:
  void Push(CapturedFrame frame);
  // The pending frames (newest per Kinect, ordered by capture time), waiting up to
  // `timeout` for at least one; empty on time-out or after Close().
  [[nodiscard]] std::vector<CapturedFrame> TakeAll(std::chrono::milliseconds timeout);
  void Close();

  [[nodiscard]] std::int64_t delivered() const;
  [[nodiscard]] std::int64_t dropped() const;

 private:
  mutable std::mutex mutex_;
  std::condition_variable arrived_;
  std::map<int, CapturedFrame> pending_;  // By sensor id.
  std::int64_t delivered_ = 0;
  std::int64_t dropped_ = 0;
  bool closed_ = false;
};

}  // namespace dynamap::app::runtime
