// The sensor thread of a mission replayed from a recording: hands the recorded odometry,
// gyro, depth frames (with their labels and true poses when the recording has them) to
// the mediator in recorded time, as fast as the workers take them (speed 0) or paced.
// The robot cannot be steered: planning and the collision guard run and show what they
// would do, but their commands go nowhere. The run ends with the recording.
#pragma once

#include <cstddef>
#include <cstdint>

#include "dynamap/app/runtime/Mediator.hpp"
#include "dynamap/app/runtime/SensorDriver.hpp"
#include "dynamap/mapping/MotionModel.hpp"
#include "dynamap/robotio/RecordingReader.hpp"

namespace dynamap::app::runtime {

struct RecordingDriverConfig {
  double step_s = 0.01;            // s of recorded time per step.
  double max_time_s = 1e9;         // s, the replay stops here if the recording is longer.
  double control_period_s = 0.05;  // s, lockstep: control must have run this recently.
  double replan_period_s = 0.5;    // s, lockstep: planning must have run this recently.
};

class RecordingDriver final : public SensorDriver {
 public:
  // `reader` is borrowed and must outlive the driver.
  RecordingDriver(const robotio::RecordingReader& reader, Mediator& mediator,
                  RecordingDriverConfig config);

  void Run() override;
  // True when the replay reached the end of the recording (or max_time_s).
  [[nodiscard]] bool reached_time_limit() const override { return reached_end_; }
  [[nodiscard]] int recording_errors() const override { return 0; }
  // The unreadable frame that ended the replay, if one did.
  [[nodiscard]] std::optional<std::string> device_error() const override { return error_; }

 private:
  // Publishes every entry stamped up to t_ns; false when a frame cannot be read.
  bool PublishUpTo(std::int64_t t_ns);

  const robotio::RecordingReader& reader_;
  Mediator& mediator_;
  RecordingDriverConfig config_;
  mapping::Trajectory2D truth_;  // The recorded true base path, for labelled frames.
  std::size_t next_odometry_ = 0, next_imu_ = 0, next_truth_ = 0, next_frame_ = 0;
  std::int64_t end_ns_ = 0;
  bool reached_end_ = false;
  std::optional<std::string> error_;
};

}  // namespace dynamap::app::runtime
