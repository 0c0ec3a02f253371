// Reads a dynamap recording or a real TUM RGB-D sequence folder. A cut-off recording is
// read up to its last whole entry; what was dropped is reported in warnings().
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/Recording.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::robotio {

struct DepthEntry {
  int sensor_id = 0;
  std::int64_t received_ns = 0;  // Stamp from the index file.
  std::string file;              // Absolute path of the image.
};

class RecordingReader {
 public:
  // Errors name the directory and the file that is missing or malformed.
  [[nodiscard]] static Expected<RecordingReader> Open(const std::string& dir);

  [[nodiscard]] const std::string& dir() const { return dir_; }
  [[nodiscard]] const Rig& rig() const { return rig_; }
  [[nodiscard]] const RecordingMeta& meta() const { return meta_; }
  [[nodiscard]] bool is_tum_sequence() const { return meta_.source == "tum"; }

  // All depth entries of all sensors, ordered by receive stamp.
  [[nodiscard]] const std::vector<DepthEntry>& depth_entries() const { return depth_; }
  [[nodiscard]] const std::vector<DepthEntry>& label_entries() const { return labels_; }
  [[nodiscard]] const std::vector<OdometryReading>& odometry() const { return odometry_; }
  [[nodiscard]] const std::vector<ImuReading>& imu() const { return imu_; }
  [[nodiscard]] const Trajectory& ground_truth() const { return ground_truth_; }
  [[nodiscard]] const std::vector<std::string>& warnings() const { return warnings_; }
  // Stamps (ns) of the first and last odometry, gyro or depth entry (depth by receive
  // stamp): the span a replay runs over. Both 0 when there is none.
  [[nodiscard]] std::int64_t first_stamp_ns() const;
  [[nodiscard]] std::int64_t last_stamp_ns() const;

  // Takes each Kinect's pose and latency from `rig` (e.g. a newer calibration) instead of
  // the recorded ones; intrinsics, rates and ranges stay the recording's. The rig must have
  // the recording's Kinects, matched by id; `source` names it in errors.
  [[nodiscard]] Status UseExtrinsics(const Rig& rig, const std::string& source);

  // Loads one frame (millimetres, capture stamp = receive stamp - rig latency).
  [[nodiscard]] Expected<DepthFrame> LoadDepth(const DepthEntry& entry) const;
  // The label image recorded for the same sensor and receive stamp, if any.
  [[nodiscard]] std::optional<LabelFrame> LoadLabels(const DepthEntry& depth_entry) const;

 private:
  std::string dir_;
  Rig rig_;
  RecordingMeta meta_;
  std::vector<DepthEntry> depth_;
  std::vector<DepthEntry> labels_;
  std::map<std::pair<int, std::int64_t>, std::string> label_files_;
  std::vector<OdometryReading> odometry_;
  std::vector<ImuReading> imu_;
  Trajectory ground_truth_;
  std::vector<std::string> warnings_;
};

// A single TUM depth PNG → frame in millimetres with the default Kinect intrinsics.
[[nodiscard]] Expected<DepthFrame> ReadTumDepthPng(const std::string& file);

}  // namespace dynamap::robotio
