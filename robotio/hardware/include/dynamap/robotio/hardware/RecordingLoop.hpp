// The manual-driving recording loop behind `dynamap record --device` (docs/HARDWARE.md,
// "Recording on the robot"): gamepad → base commands; base odometry, gyro rates and depth
// frames → a recording. It ends on the duration, the pad's Start button, an interrupt or
// the first device or disk error; the base is then stopped and everything already
// received is written before it returns.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/robotio/Devices.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"
#include "dynamap/robotio/hardware/GamepadTeleop.hpp"

namespace dynamap::robotio::hardware {

struct RecordingLoopConfig {
  std::int64_t origin_ns = 0;    // Host monotonic ns that is t = 0 in the recording; readings
                                 // stamped earlier (queued while devices opened) are dropped.
  double duration_s = 0.0;       // s to record; 0 = until Start, an interrupt or an error.
  int teleop_wait_ms = 10;       // ms the loop waits for pad events per cycle (its period).
  int camera_grab_ms = 100;      // ms a camera thread waits in one Grab call.
  int camera_silence_ms = 2000;  // ms without a frame before a camera counts as lost.
  int max_queued_frames = 8;     // Depth frames waiting for the disk; more are dropped.
};

struct RecordingCamera {
  DepthCameraInterface* camera = nullptr;
  std::string name;  // Names it in errors, e.g. "Kinect kinect0 (serial:A00361A01234)".
};

// Borrowed devices; the loop owns none of them.
struct RecordingSources {
  DriveBaseInterface* base = nullptr;    // Required.
  GamepadTeleop* teleop = nullptr;       // Required: drives the base, Start ends the run.
  ImuInterface* imu = nullptr;           // Optional.
  std::vector<RecordingCamera> cameras;  // Optional; sensor ids index the rig's Kinects.
};

enum class RecordingEnd { kDuration, kFinishButton, kInterrupted, kDeviceError, kWriteError };
// "duration", "finish_button", "interrupted", "device_error", "write_error".
[[nodiscard]] const char* RecordingEndName(RecordingEnd end);

struct RecordingProgress {
  double elapsed_s = 0.0;             // s since origin_ns.
  std::uint64_t odometry = 0;         // Odometry readings written.
  std::uint64_t imu = 0;              // Gyro readings written.
  std::vector<std::uint64_t> frames;  // Depth frames written, per camera.
  std::uint64_t dropped_frames = 0;   // Depth frames dropped because the disk lagged.
  bool deadman_held = false;          // The pad's dead-man button is down.
  VelocityCommand command;            // Last command sent to the base.
};

struct RecordingLoopResult {
  RecordingEnd end = RecordingEnd::kDuration;
  std::optional<Error> error;  // For kDeviceError and kWriteError: names the device or file.
  RecordingProgress totals;    // Final counts, everything written.
};

// Runs until one of the ends above; `interrupt` is polled every cycle (a signal handler
// may set it); `on_progress` is called every cycle from the calling thread.
[[nodiscard]] RecordingLoopResult RunRecordingLoop(
    const RecordingLoopConfig& config, const RecordingSources& sources, RecordingWriter& writer,
    const std::atomic<bool>& interrupt,
    const std::function<void(const RecordingProgress&)>& on_progress);

}  // namespace dynamap::robotio::hardware
