// A gyro speaking the Xsens MT protocol (MTi series, MTData2 output) behind ImuInterface:
// reads rate of turn on a background thread and rotates it into the base frame.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "dynamap/robotio/Devices.hpp"
#include "dynamap/robotio/hardware/SerialPort.hpp"
#include "dynamap/robotio/hardware/XsensProtocol.hpp"

namespace dynamap::robotio::hardware {

struct XsensImuConfig {
  std::string device = "/dev/dynamap_imu";  // Serial device of the MTi (USB or RS-232).
  int baud = 115200;                        // Bd, the MTi factory default.
  Eigen::Vector3d mount_rpy_deg = Eigen::Vector3d::Zero();  // deg, R_base_imu as roll, pitch, yaw.
  int silence_timeout_ms = 500;             // ms without a sample before the link is lost.
};

struct XsensLinkStats {
  std::uint64_t messages = 0;         // Valid messages received.
  std::uint64_t checksum_errors = 0;  // Messages dropped for a bad checksum.
  std::uint64_t skipped_bytes = 0;    // Noise bytes between messages.
  std::uint64_t samples = 0;          // Rate-of-turn samples delivered.
  std::uint64_t lost_samples = 0;     // Gaps in the device's packet counter.
  std::uint64_t device_errors = 0;    // Error messages (MID 0x42) from the device.
};

class XsensImu final : public ImuInterface {
 public:
  // Opens the port, asks the device to measure, starts the reader thread.
  [[nodiscard]] static Expected<std::unique_ptr<XsensImu>> Open(const XsensImuConfig& config);
  ~XsensImu() override;

  // Samples since the last call; after a link loss the remaining samples come first and
  // the Error (naming the device) on the call after.
  [[nodiscard]] Expected<std::vector<ImuReading>> ReadImu() override;

  [[nodiscard]] XsensLinkStats Stats() const;

 private:
  XsensImu(const XsensImuConfig& config, SerialPort port);
  void Run();
  void Handle(const XsensMessage& message, std::int64_t now_ns);
  void SetFault(const std::string& message);

  XsensImuConfig config_;
  SerialPort port_;
  XsensFrameParser parser_;
  Eigen::Matrix3d R_base_imu_;

  mutable std::mutex mutex_;  // Guards everything below.
  std::vector<ImuReading> pending_;
  std::optional<std::uint16_t> last_counter_;
  std::int64_t last_sample_ns_ = 0;
  XsensLinkStats stats_;
  std::optional<Error> fault_;

  std::atomic<bool> quit_{false};
  std::thread thread_;
};

}  // namespace dynamap::robotio::hardware
