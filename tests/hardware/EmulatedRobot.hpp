// The robot's drive devices without the robot, as a test fixture: the RMP and MTi
// emulators on pseudo-terminals and the gamepad as js_event records through a FIFO opened
// by path, in a scratch folder per test; opened as `dynamap record/explore --device` do.
#pragma once

#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/joystick.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <string>

#include "PtyPair.hpp"
#include "RmpEmulator.hpp"
#include "XsensEmulator.hpp"
#include "dynamap/robotio/hardware/RecordingDevices.hpp"

namespace dynamap::robotio::hardware::test {

class EmulatedRobotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string name = ::testing::UnitTest::GetInstance()->current_test_info()->name();
    dir_ = std::filesystem::temp_directory_path() /
           ("dynamap_robot_" + std::to_string(::getpid()) + "_" + name);
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
    pad_path_ = (dir_ / "js0").string();
    ASSERT_EQ(::mkfifo(pad_path_.c_str(), 0600), 0);
    config_.rmp.device = rmp_pty_.slave_path();
    config_.imu.emplace();
    config_.imu->device = imu_pty_.slave_path();
    config_.pad.device = pad_path_;
  }
  void TearDown() override {
    if (pad_fd_ >= 0) ::close(pad_fd_);
    std::filesystem::remove_all(dir_);
  }

  // Opens base, gyro and pad from config_, then the pad's writing end.
  void OpenDevices() {
    Expected<RecordingDevices> devices = OpenDriveDevices(config_);
    ASSERT_TRUE(devices.ok()) << devices.error().message;
    devices_ = std::move(devices).value();
    pad_fd_ = ::open(pad_path_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    ASSERT_GE(pad_fd_, 0);
  }
  // One joystick event, as the kernel would deliver it.
  void Pad(std::uint8_t type, std::uint8_t number, std::int16_t value) {
    js_event event{};
    event.type = type;
    event.number = number;
    event.value = value;
    ASSERT_EQ(::write(pad_fd_, &event, sizeof event), static_cast<ssize_t>(sizeof event));
  }

  std::filesystem::path dir_;
  std::string pad_path_;
  int pad_fd_ = -1;
  PtyPair rmp_pty_;
  PtyPair imu_pty_;
  RmpEmulator rmp_{rmp_pty_};
  XsensEmulator imu_{imu_pty_};
  DriveDevicesConfig config_;
  RecordingDevices devices_;
};

}  // namespace dynamap::robotio::hardware::test
