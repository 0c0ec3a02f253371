// A recording of the guided sequence (the robot driven by hand: standing still, turns,
// straight runs, arcs) fed to a CalibrationSession in recorded order, as `dynamap
// calibrate --log` and the Calibration workspace replay it: odometry, gyro and depth
// merged by stamp, and the floor step ended when the wheels first move.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "dynamap/calibration/CalibrationSession.hpp"
#include "dynamap/robotio/RecordingReader.hpp"

namespace dynamap::calibration {

class CaptureReplay {
 public:
  // `reader` is borrowed and must outlive the replay.
  explicit CaptureReplay(const robotio::RecordingReader& reader);

  // Feeds every entry stamped up to `until_ns` (recorded time). Depth frames fed are
  // also kept in `newest_depth` (indexed by sensor id) when given. An unreadable frame
  // is an Error naming its file; what came before it stays fed.
  [[nodiscard]] robotio::Status FeedUntil(CalibrationSession& session, std::int64_t until_ns,
                                          std::vector<robotio::DepthFrame>* newest_depth);

  [[nodiscard]] bool done() const;
  // Share of the depth frames fed so far, [0, 1].
  [[nodiscard]] double fraction() const;


 private:
  const robotio::RecordingReader& reader_;
  std::size_t next_odometry_ = 0, next_imu_ = 0, next_depth_ = 0;
};

}  // namespace dynamap::calibration
