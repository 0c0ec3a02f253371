// One depth image as a Kinect delivers it: 16-bit depth in millimetres, 0 = no measurement.
#pragma once

#include <cstdint>
#include <vector>

#include "dynamap/robotio/Intrinsics.hpp"

namespace dynamap::robotio {

struct DepthFrame {
  int sensor_id = 0;             // Index of the Kinect in the rig (0, 1, ...).
  std::int64_t stamp_ns = 0;     // Capture time: the instant the image shows (monotonic ns).
  std::int64_t received_ns = 0;  // Host time the frame arrived (capture + sensor latency).
  int width = 0;                 // px.
  int height = 0;                // px.
  Intrinsics intrinsics;         // Of this image's resolution.
  std::vector<std::uint16_t> depth_mm;  // Row-major, width * height; 0 = missing.

  [[nodiscard]] std::uint16_t At(int u, int v) const { return depth_mm[v * width + u]; }
  [[nodiscard]] bool Valid() const {
    return width > 0 && height > 0 &&
           depth_mm.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
};

// Ground-truth label image that the simulator renders beside each depth frame.
// Value 0 = no hit; otherwise (object index + 1), with kDynamicBit set when the surface
// belongs to something that must not end in the static map.
struct LabelFrame {
  static constexpr std::uint16_t kDynamicBit = 0x8000;
  static constexpr std::uint16_t kIdMask = 0x7fff;

  int sensor_id = 0;
  std::int64_t stamp_ns = 0;  // Capture time, equal to the matching DepthFrame's.
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> labels;

  [[nodiscard]] static bool IsDynamic(std::uint16_t label) { return (label & kDynamicBit) != 0; }
  [[nodiscard]] static int ObjectIndex(std::uint16_t label) { return (label & kIdMask) - 1; }
};

}  // namespace dynamap::robotio
