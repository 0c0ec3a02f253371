// The Segway RMP 50/100/200 drive base over its USB/serial interface (RmpProtocol): sends
// the motion command at a steady rate, turns wheel-travel status into odometry, and stops
// the base when commands stop coming (watchdog) or the base stops answering.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "dynamap/robotio/Devices.hpp"
#include "dynamap/robotio/hardware/RmpProtocol.hpp"
#include "dynamap/robotio/hardware/SerialPort.hpp"

namespace dynamap::robotio::hardware {

// Defaults are the RMP 50 figures of the RMP interface guide (docs/HARDWARE.md).
struct RmpConfig {
  std::string device = "/dev/segway_rmp";  // Serial device of the RMP USB interface.
  int baud = 460800;                      // Bd of the USB interface's serial link.
  double wheel_counts_per_m = 40181.0;    // Status 0x403 counts per metre of wheel travel.
  double velocity_counts_per_mps = 401.0;  // Command counts per m/s forward.
  double turn_counts_per_radps = 446.9;   // Command counts per rad/s (7.8 counts per deg/s).
  double max_velocity_mps = 1.0;          // m/s, commands are clamped to ±this.
  double max_omega_radps = 1.0;           // rad/s, commands are clamped to ±this.
  int command_period_ms = 20;             // ms between motion commands sent (the heartbeat).
  int command_timeout_ms = 300;           // ms without Command() before the watchdog stops.
  int status_timeout_ms = 500;            // ms without any status before the link is lost.
};

struct RmpLinkStats {
  std::uint64_t frames = 0;            // Valid frames received.
  std::uint64_t checksum_errors = 0;   // Frames dropped for a bad checksum.
  std::uint64_t skipped_bytes = 0;     // Noise bytes between frames.
  std::uint64_t commands_sent = 0;     // Motion commands written.
  std::uint64_t watchdog_stops = 0;    // Times the watchdog zeroed a stale command.
  std::optional<double> battery_v;     // Last powerbase battery voltage (V).
  std::optional<std::uint16_t> mode;   // Last operational mode.
};

class RmpDriver final : public DriveBaseInterface {
 public:
  // Opens the port and starts the I/O thread; the Error names the device.
  [[nodiscard]] static Expected<std::unique_ptr<RmpDriver>> Open(const RmpConfig& config);
  ~RmpDriver() override;  // Commands a stop, then closes the link.

  // Error once the link is lost; the base is then already commanded to stop.
  [[nodiscard]] Status Command(const VelocityCommand& command) override;
  // Readings since the last call; after a link loss the remaining readings are returned
  // first and the Error on the call after.
  [[nodiscard]] Expected<std::vector<OdometryReading>> ReadOdometry() override;
  void Stop() override;

  [[nodiscard]] RmpLinkStats Stats() const;
  [[nodiscard]] std::optional<Error> Fault() const;

 private:
  RmpDriver(const RmpConfig& config, SerialPort port);
  void Run();
  void HandleMessage(const RmpCanMessage& message, std::int64_t now_ns);
  void SetFault(const std::string& message);
  void SendCommand(std::int64_t now_ns);

  RmpConfig config_;
  SerialPort port_;
  RmpFrameParser parser_;

  mutable std::mutex mutex_;  // Guards everything below.
  VelocityCommand command_;
  std::int64_t last_command_ns_ = 0;
  std::int64_t last_status_ns_ = 0;
  bool watchdog_tripped_ = false;
  std::vector<OdometryReading> pending_;
  std::optional<std::int32_t> last_left_counts_;
  std::optional<std::int32_t> last_right_counts_;
  std::int64_t left_total_counts_ = 0;
  std::int64_t right_total_counts_ = 0;
  RmpLinkStats stats_;
  std::optional<Error> fault_;

  std::atomic<bool> quit_{false};
  std::thread thread_;
};

}  // namespace dynamap::robotio::hardware
