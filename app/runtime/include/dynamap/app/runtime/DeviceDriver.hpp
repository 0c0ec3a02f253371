// The sensor thread of a mission on the real robot: reads the base's odometry, the gyro
// and every Kinect, hands them to the mediator (and the recording), and passes the control
// worker's newest command to the base only while the operator holds the dead-man switch.
// The first device that fails ends the mission: the base is stopped, and what arrived
// before is kept (docs/HARDWARE.md, "Running a mission on the robot").
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/app/runtime/Mediator.hpp"
#include "dynamap/app/runtime/SensorDriver.hpp"
#include "dynamap/robotio/Devices.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"

namespace dynamap::app::runtime {

struct DeviceCamera {
  robotio::DepthCameraInterface* camera = nullptr;
  std::string name;  // For messages, e.g. "Kinect kinect0 (serial:A00361A01234)".
};

// Borrowed devices; the driver owns none of them.
struct DeviceSources {
  robotio::DriveBaseInterface* base = nullptr;  // Required.
  robotio::ImuInterface* imu = nullptr;         // Optional.
  std::vector<DeviceCamera> cameras;            // Sensor ids index the rig's Kinects.
  // The operator's dead-man switch (the pad's LB): true while held, waiting at most the
  // given time for news (it paces the loop); an Error when the switch is gone. Required.
  std::function<robotio::Expected<bool>(std::chrono::milliseconds)> deadman;
};

struct DeviceDriverConfig {
  // Host monotonic ns that is mission time 0 (0: when Run starts); earlier readings
  // (queued while the devices opened) are dropped.
  std::int64_t origin_ns = 0;
  double max_time_s = 1200.0;    // s, the mission ends here.
  int cycle_ms = 10;             // ms, period of the loop (the dead-man wait).
  int camera_grab_ms = 100;      // ms a camera thread waits in one Grab call.
  int camera_silence_ms = 2000;  // ms without a frame before a camera counts as lost.
};

class DeviceDriver final : public SensorDriver {
 public:
  DeviceDriver(DeviceSources sources, Mediator& mediator, DeviceDriverConfig config,
               robotio::RecordingWriter* recording);

  void Run() override;
  [[nodiscard]] bool reached_time_limit() const override { return reached_time_limit_; }
  [[nodiscard]] int recording_errors() const override { return recording_errors_; }
  [[nodiscard]] std::optional<std::string> device_error() const override;
  // Cycles in which the base got the planner's command (dead-man held) and in which it got
  // zero instead.
  [[nodiscard]] std::int64_t commands_passed() const { return commands_passed_; }
  [[nodiscard]] std::int64_t commands_held_back() const { return commands_held_back_; }

 private:
  void GrabLoop(std::size_t index);
  void Fail(const std::string& message);
  // One cycle; false when a device failed.
  bool Cycle(std::int64_t now_ns, bool deadman_held);

  DeviceSources sources_;
  Mediator& mediator_;
  DeviceDriverConfig config_;
  robotio::RecordingWriter* recording_;
  bool reached_time_limit_ = false;
  int recording_errors_ = 0;
  std::int64_t commands_passed_ = 0;
  std::int64_t commands_held_back_ = 0;

  mutable std::mutex mutex_;  // Guards the members below (camera threads write them).
  std::vector<robotio::DepthFrame> pending_;
  std::vector<std::int64_t> last_frame_host_ns_;  // Per camera, host monotonic ns.
  std::optional<std::string> error_;
  bool stop_cameras_ = false;
};

}  // namespace dynamap::app::runtime
