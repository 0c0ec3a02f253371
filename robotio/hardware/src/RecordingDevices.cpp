#include "dynamap/robotio/hardware/RecordingDevices.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <thread>

namespace dynamap::robotio::hardware {
namespace {

// Polls `answered` every few ms until it holds, `failed` returns an Error, or `timeout_ms`
// passes; true when the device answered.
Expected<bool> WaitForFirstData(int timeout_ms, const std::function<bool()>& answered,
                                const std::function<std::optional<Error>()>& failed) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(timeout_ms);
  for (;;) {
    if (std::optional<Error> error = failed()) return *error;
    if (answered()) return true;
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

bool IsIndex(const std::string& spec) {
  return !spec.empty() && spec.size() <= 3 &&
         std::all_of(spec.begin(), spec.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

RecordingSources RecordingDevices::Sources() {
  RecordingSources sources;
  sources.base = base.get();
  sources.teleop = pad ? &*pad : nullptr;
  sources.imu = imu.get();
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    sources.cameras.push_back({cameras[i].get(), i < camera_names.size() ? camera_names[i] : ""});
  }
  return sources;
}

Expected<RecordingDevices> OpenDriveDevices(const DriveDevicesConfig& config) {
  RecordingDevices devices;
  Expected<std::unique_ptr<RmpDriver>> base = RmpDriver::Open(config.rmp);
  if (!base) return base.error();
  devices.base = std::move(base).value();
  RmpDriver& rmp = *devices.base;
  Expected<bool> base_answered = WaitForFirstData(
      config.first_data_timeout_ms, [&] { return rmp.Stats().frames > 0; },
      [&] { return rmp.Fault(); });
  if (!base_answered) return base_answered.error();
  if (!*base_answered) {
    return Error{"Segway RMP on " + config.rmp.device + ": no status message within " +
                 std::to_string(config.first_data_timeout_ms) +
                 " ms of opening (base switched off, or this port is not the RMP's USB "
                 "interface?)"};
  }

  if (config.imu) {
    Expected<std::unique_ptr<XsensImu>> imu = XsensImu::Open(*config.imu);
    if (!imu) return imu.error();
    devices.imu = std::move(imu).value();
    XsensImu& gyro = *devices.imu;
    Expected<bool> imu_answered = WaitForFirstData(
        config.first_data_timeout_ms, [&] { return gyro.Stats().samples > 0; },
        [&]() -> std::optional<Error> {
          // Samples read here predate the recording's origin and would be dropped anyway.
          Expected<std::vector<ImuReading>> samples = gyro.ReadImu();
          if (!samples) return samples.error();
          return std::nullopt;
        });
    if (!imu_answered) return imu_answered.error();
    if (!*imu_answered) {
      return Error{"Xsens IMU on " + config.imu->device + ": no rate-of-turn sample within " +
                   std::to_string(config.first_data_timeout_ms) +
                   " ms of opening (not an MTi, wrong baud rate, or no MTData2 output "
                   "configured?)"};
    }
  }

  Expected<GamepadTeleop> pad = GamepadTeleop::Open(config.pad);
  if (!pad) return pad.error();
  devices.pad.emplace(std::move(pad).value());
  return devices;
}

Expected<std::vector<RecordingCameraConfig>> CameraConfigsForRig(
    const Rig& rig, const std::vector<std::string>& specs) {
  const std::size_t kinects = rig.kinects.size();
  if (specs.empty() && kinects > 1) {
    std::string connected = "none";
    if (Expected<std::vector<OpenNiDeviceInfo>> list = ListOpenNiDevices(); list.ok()) {
      connected.clear();
      for (const OpenNiDeviceInfo& d : *list) connected += (connected.empty() ? "" : ", ") + d.uri;
    }
    return Error{"the rig has " + std::to_string(kinects) +
                 " Kinects: name one camera per Kinect, in rig order (serial:XYZ stays right "
                 "when USB ports change; connected now: " +
                 connected + ")"};
  }
  if (!specs.empty() && specs.size() != kinects) {
    return Error{std::to_string(specs.size()) + " camera(s) named for a rig with " +
                 std::to_string(kinects) + " Kinect(s); name one per Kinect, in rig order"};
  }
  std::optional<std::vector<OpenNiDeviceInfo>> listed;
  std::vector<RecordingCameraConfig> configs;
  for (std::size_t i = 0; i < kinects; ++i) {
    const KinectMount& mount = rig.kinects[i];
    RecordingCameraConfig config;
    config.camera.device = specs.empty() ? std::string() : specs[i];
    if (IsIndex(config.camera.device)) {
      if (!listed) {
        Expected<std::vector<OpenNiDeviceInfo>> list = ListOpenNiDevices();
        if (!list) return Error{"camera " + config.camera.device + ": " + list.error().message};
        listed = *list;
      }
      const auto index = static_cast<std::size_t>(std::stoi(config.camera.device));
      if (index >= listed->size()) {
        return Error{"camera " + config.camera.device + ": OpenNI2 lists only " +
                     std::to_string(listed->size()) + " camera(s), numbered from 0"};
      }
      config.camera.device = (*listed)[index].uri;
    }
    config.camera.sensor_id = static_cast<int>(i);
    config.camera.width = mount.intrinsics.width;
    config.camera.height = mount.intrinsics.height;
    config.camera.fps = static_cast<int>(std::lround(mount.rate_hz));
    config.camera.intrinsics = mount.intrinsics;
    config.name =
        "Kinect " + mount.id + " (" +
        (config.camera.device.empty() ? "the only camera connected" : config.camera.device) + ")";
    configs.push_back(std::move(config));
  }
  return configs;
}

Expected<std::vector<std::unique_ptr<OpenNiCamera>>> OpenRecordingCameras(
    const std::vector<RecordingCameraConfig>& configs) {
  std::vector<std::unique_ptr<OpenNiCamera>> cameras;
  for (const RecordingCameraConfig& config : configs) {
    Expected<std::unique_ptr<OpenNiCamera>> camera = OpenNiCamera::Open(config.camera);
    if (!camera) return Error{config.name + ": " + camera.error().message};
    cameras.push_back(std::move(camera).value());
  }
  return cameras;
}

Status OpenRigCameras(const Rig& rig, const std::vector<std::string>& specs,
                      RecordingDevices* devices) {
  auto configs = CameraConfigsForRig(rig, specs);
  if (!configs) return configs.error();
  auto opened = OpenRecordingCameras(*configs);
  if (!opened) return opened.error();
  devices->cameras = std::move(opened).value();
  devices->camera_names.clear();
  for (const auto& c : *configs) devices->camera_names.push_back(c.name);
  return Ok{};
}

}  // namespace dynamap::robotio::hardware
