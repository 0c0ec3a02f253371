// OpenNI2 recordings (.oni) into dynamap's recording format: one camera's depth frames,
// a rig of one level camera and no odometry, so that `dynamap map` tracks the camera by
// registration alone, as for a TUM RGB-D sequence.
#pragma once

#include <chrono>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "dynamap/robotio/Devices.hpp"
#include "dynamap/robotio/Intrinsics.hpp"

namespace dynamap::robotio::hardware {

struct UnpackedFrames {
  std::size_t frames = 0;
  int width = 0;   // px, of the frames written.
  int height = 0;  // px.
};

// Reads `camera` until `frame_count` frames (when known), or until no frame came for
// `idle_timeout`, and writes them to a new recording in `dir` (source "hardware",
// `note` in meta.yaml). `intrinsics` (at 640 × 480) is scaled to the frames' size.
// No frame at all is an Error that names `what` and the frames it should have had.
// `progress` gets the share of frame_count done (when known).
[[nodiscard]] Expected<UnpackedFrames> UnpackDepthFrames(
    DepthCameraInterface& camera, const std::string& what, std::optional<int> frame_count,
    const Intrinsics& intrinsics, const std::string& dir, const std::string& note,
    std::chrono::milliseconds idle_timeout, const std::function<void(double)>& progress);

// The same for an .oni file opened through OpenNI2's file device.
[[nodiscard]] Expected<UnpackedFrames> UnpackOniFile(
    const std::string& oni_file, const std::string& dir,
    const std::function<void(double)>& progress);

}  // namespace dynamap::robotio::hardware
