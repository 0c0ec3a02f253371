#include "dynamap/robotio/hardware/RmpDriver.hpp"

#include <algorithm>
#include <cmath>

#include "dynamap/robotio/hardware/MonotonicClock.hpp"

namespace dynamap::robotio::hardware {
namespace {

constexpr std::chrono::milliseconds kWriteTimeout{100};

}  // namespace

Expected<std::unique_ptr<RmpDriver>> RmpDriver::Open(const RmpConfig& config) {
  Expected<SerialPort> port = SerialPort::Open(config.device, config.baud);
  if (!port) return Error{"Segway RMP: " + port.error().message};
  std::unique_ptr<RmpDriver> driver(new RmpDriver(config, std::move(port).value()));
  driver->thread_ = std::thread([raw = driver.get()] { raw->Run(); });
  return driver;
}

RmpDriver::RmpDriver(const RmpConfig& config, SerialPort port)
    : config_(config), port_(std::move(port)) {
  const std::int64_t now = MonotonicNanos();
  last_command_ns_ = now;
  last_status_ns_ = now;
}

RmpDriver::~RmpDriver() {
  Stop();
  quit_ = true;
  if (thread_.joinable()) thread_.join();
  // A last zero command so the base does not wait for its own timeout.
  std::lock_guard<std::mutex> lock(mutex_);
  if (!fault_) {
    const auto frame = EncodeRmpCommandFrame(MakeRmpMotionCommand(0, 0));
    (void)port_.Write({frame.begin(), frame.end()}, kWriteTimeout);
  }
}

Status RmpDriver::Command(const VelocityCommand& command) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (fault_) return *fault_;
  command_ = command;
  command_.v = std::clamp(command.v, -config_.max_velocity_mps, config_.max_velocity_mps);
  command_.omega = std::clamp(command.omega, -config_.max_omega_radps, config_.max_omega_radps);
  last_command_ns_ = MonotonicNanos();
  watchdog_tripped_ = false;
  return Ok{};
}

Expected<std::vector<OdometryReading>> RmpDriver::ReadOdometry() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (pending_.empty() && fault_) return *fault_;
  std::vector<OdometryReading> readings;
  readings.swap(pending_);
  return readings;
}

void RmpDriver::Stop() {
  std::lock_guard<std::mutex> lock(mutex_);
  command_ = VelocityCommand{};
  last_command_ns_ = MonotonicNanos();
}

RmpLinkStats RmpDriver::Stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  RmpLinkStats stats = stats_;
  stats.frames = parser_.counters().frames;
  stats.checksum_errors = parser_.counters().checksum_errors;
  stats.skipped_bytes = parser_.counters().skipped_bytes;
  return stats;
}

std::optional<Error> RmpDriver::Fault() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return fault_;
}

void RmpDriver::SetFault(const std::string& message) {
  if (!fault_) fault_ = Error{"Segway RMP on " + config_.device + ": " + message};
  command_ = VelocityCommand{};
}

void RmpDriver::SendCommand(std::int64_t now_ns) {
  // Caller holds mutex_. The watchdog: a command older than the timeout is replaced by a
  // stop, so a crashed or stalled caller cannot leave the base driving.
  const std::int64_t timeout_ns = std::int64_t{config_.command_timeout_ms} * 1'000'000;
  if (now_ns - last_command_ns_ > timeout_ns && !watchdog_tripped_) {
    watchdog_tripped_ = true;
    if (command_.v != 0.0 || command_.omega != 0.0) ++stats_.watchdog_stops;
    command_ = VelocityCommand{};
  }
  const int v_counts = static_cast<int>(std::lround(command_.v * config_.velocity_counts_per_mps));
  const int t_counts =
      static_cast<int>(std::lround(command_.omega * config_.turn_counts_per_radps));
  const auto frame = EncodeRmpCommandFrame(MakeRmpMotionCommand(v_counts, t_counts));
  const Status written = port_.Write({frame.begin(), frame.end()}, kWriteTimeout);
  if (!written) {
    SetFault(written.error().message);
    return;
  }
  ++stats_.commands_sent;
}

void RmpDriver::HandleMessage(const RmpCanMessage& message, std::int64_t now_ns) {
  // Caller holds mutex_.
  if (message.id < kRmpStatusFirstId || message.id > kRmpStatusLastId) return;
  last_status_ns_ = now_ns;
  const RmpStatus status = DecodeRmpStatus(message);
  if (status.powerbase_battery_v) stats_.battery_v = status.powerbase_battery_v;
  if (status.operational_mode) stats_.mode = status.operational_mode;
  if (!status.left_wheel_counts || !status.right_wheel_counts) return;
  // The base's 32-bit counters wrap; accumulate differences in 64 bits, starting at 0.
  if (last_left_counts_) {
    left_total_counts_ += static_cast<std::int32_t>(
        static_cast<std::uint32_t>(*status.left_wheel_counts) -
        static_cast<std::uint32_t>(*last_left_counts_));
    right_total_counts_ += static_cast<std::int32_t>(
        static_cast<std::uint32_t>(*status.right_wheel_counts) -
        static_cast<std::uint32_t>(*last_right_counts_));
  }
  last_left_counts_ = status.left_wheel_counts;
  last_right_counts_ = status.right_wheel_counts;
  OdometryReading reading;
  reading.stamp_ns = now_ns;
  reading.left_m = static_cast<double>(left_total_counts_) / config_.wheel_counts_per_m;
  reading.right_m = static_cast<double>(right_total_counts_) / config_.wheel_counts_per_m;
  pending_.push_back(reading);
}

void RmpDriver::Run() {
  const std::int64_t period_ns = std::int64_t{config_.command_period_ms} * 1'000'000;
  const std::int64_t status_timeout_ns = std::int64_t{config_.status_timeout_ms} * 1'000'000;
  std::int64_t next_send_ns = MonotonicNanos();
  while (!quit_) {
    const std::int64_t wait_ns = std::max<std::int64_t>(0, next_send_ns - MonotonicNanos());
    Expected<std::vector<std::uint8_t>> bytes =
        port_.Read(std::chrono::milliseconds(wait_ns / 1'000'000));
    const std::int64_t now = MonotonicNanos();
    std::lock_guard<std::mutex> lock(mutex_);
    if (!bytes) {
      // The link is gone: nothing more can be sent. The RMP stops on its own when its
      // command stream ends (the base's own timeout), and callers now get the Error.
      SetFault(bytes.error().message);
      return;
    }
    for (const RmpCanMessage& message : parser_.Feed(*bytes)) HandleMessage(message, now);
    if (!fault_ && now - last_status_ns_ > status_timeout_ns) {
      SetFault("no status message for " + std::to_string(config_.status_timeout_ms) +
               " ms (base powered off or cable loose?); stopping");
    }
    if (now >= next_send_ns) {
      // After a fault the stop command keeps going out for as long as the link accepts it.
      SendCommand(now);
      next_send_ns = now + period_ns;
    }
  }
}

}  // namespace dynamap::robotio::hardware
