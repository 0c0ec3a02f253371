// The real robot's opened devices as a mission's sensor sources (dynamap explore --device,
// the Mission workspace's "Real robot" source): the pad's dead-man button (LB) gates every
// base command, its Start button asks for the end. Header-only: only programs that link
// dynamap_hardware include it.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>

#include "dynamap/app/runtime/DeviceDriver.hpp"
#include "dynamap/robotio/hardware/RecordingDevices.hpp"

namespace dynamap::app::runtime {

// What the pad said last, for front ends: progress lines, the end of the mission.
struct PadState {
  std::atomic<bool> held{false};    // LB, the dead-man button.
  std::atomic<bool> finish{false};  // Start was pressed.
};

// `devices` (base, gyro, pad, cameras) must outlive the mission that reads them.
inline DeviceSources SourcesFromRobot(robotio::hardware::RecordingDevices& devices,
                                      std::shared_ptr<PadState> pad_state) {
  DeviceSources sources;
  sources.base = devices.base.get();
  sources.imu = devices.imu.get();
  for (std::size_t i = 0; i < devices.cameras.size(); ++i) {
    sources.cameras.push_back({devices.cameras[i].get(), i < devices.camera_names.size()
                                                              ? devices.camera_names[i]
                                                              : std::string()});
  }
  robotio::hardware::GamepadTeleop* pad = devices.pad ? &*devices.pad : nullptr;
  sources.deadman = [pad, pad_state](std::chrono::milliseconds wait) -> robotio::Expected<bool> {
    if (pad == nullptr) return robotio::Error{"no gamepad: the base cannot be released"};
    auto state = pad->Update(wait);
    if (!state) return state.error();
    if (state->finish_requested) pad_state->finish = true;
    pad_state->held = state->deadman_held;
    return state->deadman_held;
  };
  return sources;
}

}  // namespace dynamap::app::runtime
