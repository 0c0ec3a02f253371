// Opening the real robot's devices for a recording (docs/HARDWARE.md, "Recording on the
// robot"): the base and the gyro must answer within a bounded wait and every Kinect of the
// rig must open, so a missing, silent or misnamed device is an Error naming it before
// anything is written.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/hardware/GamepadTeleop.hpp"
#include "dynamap/robotio/hardware/OpenNiCamera.hpp"
#include "dynamap/robotio/hardware/RecordingLoop.hpp"
#include "dynamap/robotio/hardware/RmpDriver.hpp"
#include "dynamap/robotio/hardware/XsensImu.hpp"

namespace dynamap::robotio::hardware {

struct DriveDevicesConfig {
  RmpConfig rmp;
  std::optional<XsensImuConfig> imu;  // nullopt: record without a gyro.
  GamepadConfig pad;
  int first_data_timeout_ms = 1000;  // ms to wait for the base's and the gyro's first data.
};

struct RecordingCameraConfig {
  std::string name;  // "Kinect <rig id> (<device>)", for messages.
  OpenNiCameraConfig camera;
};

// Owns what it opened; Sources() lends it to RunRecordingLoop.
struct RecordingDevices {
  std::unique_ptr<RmpDriver> base;
  std::unique_ptr<XsensImu> imu;  // Null without a gyro.
  std::optional<GamepadTeleop> pad;
  std::vector<std::unique_ptr<OpenNiCamera>> cameras;
  std::vector<std::string> camera_names;

  [[nodiscard]] RecordingSources Sources();
};

// Opens base, gyro and pad, in that order; the first that fails is the Error.
[[nodiscard]] Expected<RecordingDevices> OpenDriveDevices(const DriveDevicesConfig& config);

// One camera config per Kinect of `rig`, in rig order. `specs` names the devices: empty
// (allowed only for a one-Kinect rig: the only camera connected), or one per Kinect, each
// a URI, "serial:XYZ", a ".oni" file, or a number N for the N-th device OpenNI2 lists
// (from 0). The depth mode is the rig's resolution and rate.
[[nodiscard]] Expected<std::vector<RecordingCameraConfig>> CameraConfigsForRig(
    const Rig& rig, const std::vector<std::string>& specs);

// Opens every camera; the first that fails is the Error, naming it.
[[nodiscard]] Expected<std::vector<std::unique_ptr<OpenNiCamera>>> OpenRecordingCameras(
    const std::vector<RecordingCameraConfig>& configs);

// Both steps for `rig` (CameraConfigsForRig, OpenRecordingCameras), the cameras and their
// names put into `devices`; the first failure is the Error and leaves `devices` as it was.
[[nodiscard]] Status OpenRigCameras(const Rig& rig, const std::vector<std::string>& specs,
                                    RecordingDevices* devices);

}  // namespace dynamap::robotio::hardware
