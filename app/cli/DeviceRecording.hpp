// The real robot on the command line: its device options and their opening, shared by
// `dynamap record --device` and `dynamap explore --device`, and the recording itself:
// the robot driven with the gamepad (base odometry, gyro, Kinects) into the same recording
// format as the simulator, until Start, Ctrl-C, --duration or the first device error
// (docs/HARDWARE.md, "Recording on the robot").
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/hardware/RecordingDevices.hpp"

namespace dynamap::app {

struct DeviceOptions {
  std::string rig;          // Rig file; empty: resources/rigs/two_kinects.yaml.
  std::string out;          // New recording folder (record).
  double duration_s = 0.0;  // s; 0 = until Start, Ctrl-C or an error (record).
  int width = 0;            // px depth mode width; 0 = the rig's.
  std::string rmp_port;     // Serial device of the Segway RMP.
  std::string imu_port;     // Serial device of the Xsens gyro.
  int imu_baud = 0;         // Bd of the gyro's serial link.
  std::vector<double> imu_rpy_deg = {0.0, 0.0, 0.0};  // deg, gyro mount in base.
  bool no_imu = false;                                // Record without a gyro.
  std::string pad;                                    // Joystick device.
  std::vector<std::string> cameras;  // One per rig Kinect: URI, serial:XYZ, file.oni or index.
  bool no_cameras = false;           // Record without depth.
};

// Adds the device-only options to `command`; each needs `device_flag`. Defaults come from
// the drivers' configs.
void AddDeviceOptions(CLI::App& command, CLI::Option* device_flag, DeviceOptions& options);

// The rig file (default resources/rigs/two_kinects.yaml) at `options.width`, if given;
// a bad file fails `command`.
[[nodiscard]] robotio::Rig LoadDeviceRig(const char* command, const DeviceOptions& options);

// Opens base, gyro, pad and every Kinect of `rig`; the first missing one fails `command`
// with a message naming it.
[[nodiscard]] robotio::hardware::RecordingDevices OpenRobotDevices(const char* command,
                                                                   const DeviceOptions& options,
                                                                   const robotio::Rig& rig);

// Opens the devices (failing, before anything is written, with an error naming the one that
// is missing), records, and writes report.json; a device error after the start keeps the
// recording and fails the command with that error.
void RunDeviceRecord(const DeviceOptions& options);

}  // namespace dynamap::app
