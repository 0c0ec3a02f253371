// Appends a recording as it happens: every image is written atomically before its index
// line, and every line is flushed, so a recording cut off by a crash reads back up to its
// last whole frame.
#pragma once

#include <cstdio>
#include <map>
#include <memory>
#include <string>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/Recording.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::robotio {

class RecordingWriter {
 public:
  // Creates `dir` (it must not hold a recording already) and writes rig.yaml, meta.yaml.
  [[nodiscard]] static Expected<std::unique_ptr<RecordingWriter>> Create(
      const std::string& dir, const Rig& rig, const RecordingMeta& meta);
  ~RecordingWriter();
  RecordingWriter(const RecordingWriter&) = delete;
  RecordingWriter& operator=(const RecordingWriter&) = delete;

  // Stored under the frame's receive stamp (see Recording.hpp).
  [[nodiscard]] Status AddDepth(const DepthFrame& frame);
  [[nodiscard]] Status AddLabels(const LabelFrame& labels, std::int64_t received_ns);
  [[nodiscard]] Status AddOdometry(const OdometryReading& reading);
  [[nodiscard]] Status AddImu(const ImuReading& reading);
  [[nodiscard]] Status AddGroundTruth(const StampedPose& pose);

  [[nodiscard]] const std::string& dir() const { return dir_; }
  [[nodiscard]] int depth_frames_written() const { return depth_frames_; }

 private:
  explicit RecordingWriter(std::string dir);
  [[nodiscard]] Status AppendLine(const std::string& index_file, const std::string& line);

  std::string dir_;
  std::map<std::string, std::FILE*> files_;
  int depth_frames_ = 0;
};

}  // namespace dynamap::robotio
