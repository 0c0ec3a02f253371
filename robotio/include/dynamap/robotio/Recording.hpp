// The recording format (DESIGN.md, robotio): a TUM RGB-D compatible directory
//   depth/<stamp>.png + depth.txt       Kinect 0, 16-bit PNG, value = metres * 5000
//   depth1/<stamp>.png + depth1.txt     Kinect 1 (and depthN for further Kinects)
//   labels/, labels.txt (labels1/ ...)  simulator ground-truth label images (optional)
//   groundtruth.txt                     true base pose, TUM trajectory (optional)
//   odometry.txt                        "stamp left_m right_m" cumulative wheel distances
//   imu.txt                             "stamp wx wy wz" rad/s
//   rig.yaml, meta.yaml
// Stamps in depth.txt are the host's receive times, like a real TUM sequence; a frame's
// capture time is the receive time minus the Kinect's latency from the rig.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace dynamap::robotio {

struct RecordingMeta {
  std::string source = "simulator";  // simulator | hardware | tum
  std::string world;                 // World file the simulator ran (empty otherwise).
  std::uint64_t seed = 0;            // Simulator seed.
  double duration_s = 0.0;           // Planned duration; the data may end earlier.
  int format_version = 1;
  std::map<std::string, std::string> extra;  // Free-form notes (scenario name, host, ...).
};

// File names inside a recording directory.
namespace recording_files {
[[nodiscard]] std::string DepthDir(int sensor_id);    // "depth", "depth1", ...
[[nodiscard]] std::string DepthIndex(int sensor_id);  // "depth.txt", "depth1.txt", ...
[[nodiscard]] std::string LabelDir(int sensor_id);    // "labels", "labels1", ...
[[nodiscard]] std::string LabelIndex(int sensor_id);  // "labels.txt", "labels1.txt", ...
inline constexpr const char* kGroundTruth = "groundtruth.txt";
inline constexpr const char* kOdometry = "odometry.txt";
inline constexpr const char* kImu = "imu.txt";
inline constexpr const char* kRig = "rig.yaml";
inline constexpr const char* kMeta = "meta.yaml";
}  // namespace recording_files

}  // namespace dynamap::robotio
