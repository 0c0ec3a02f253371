// Frames from the frame queue put together into scans of one instant, one frame per
// Kinect (thesis 5.3: a scan is both Kinects' images, registered as one). The Kinects
// capture half a period apart and arrive one at a time; a lone frame waits for its
// partner, and goes alone when its own Kinect's next frame or a frame too late for it
// comes first (a Kinect that stopped delivering holds nothing back for long).
#pragma once

#include <cstdint>
#include <vector>

#include "dynamap/app/runtime/FrameQueue.hpp"

namespace dynamap::app::runtime {

class ScanAssembler {
 public:
  // `sensors`: Kinects in the rig; `max_span_ns`: longest capture-time span of one scan.
  ScanAssembler(int sensors, std::int64_t max_span_ns)
      : sensors_(sensors), max_span_ns_(max_span_ns) {}

  // Adds frames (any order) and returns the scans now complete, oldest first.
  [[nodiscard]] std::vector<std::vector<CapturedFrame>> Add(std::vector<CapturedFrame> frames);

  [[nodiscard]] std::size_t waiting() const { return held_.size(); }

 private:
  int sensors_;
  std::int64_t max_span_ns_;
  std::vector<CapturedFrame> held_;  // The newest scan, not yet complete.
};

}  // namespace dynamap::app::runtime
