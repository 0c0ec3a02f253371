#include "dynamap/app/runtime/DeviceDriver.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <thread>

namespace dynamap::app::runtime {
namespace {

// Host monotonic ns: the clock every hardware driver stamps with (std::chrono's steady
// clock, as robotio::hardware::MonotonicNanos).
std::int64_t HostNanos() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

template <typename Reading>
void Rebase(std::vector<Reading>* readings, std::int64_t origin_ns) {
  std::vector<Reading> kept;
  for (Reading r : *readings) {
    if (r.stamp_ns < origin_ns) continue;
    r.stamp_ns -= origin_ns;
    kept.push_back(r);
  }
  *readings = std::move(kept);
}

}  // namespace

DeviceDriver::DeviceDriver(DeviceSources sources, Mediator& mediator, DeviceDriverConfig config,
                           robotio::RecordingWriter* recording)
    : sources_(std::move(sources)),
      mediator_(mediator),
      config_(config),
      recording_(recording),
      last_frame_host_ns_(sources_.cameras.size(), 0) {}

std::optional<std::string> DeviceDriver::device_error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

void DeviceDriver::Fail(const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!error_) error_ = message;
}

void DeviceDriver::GrabLoop(std::size_t index) {
  const DeviceCamera& source = sources_.cameras[index];
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (stop_cameras_ || error_) return;
    }
    auto grabbed = source.camera->Grab(std::chrono::milliseconds(config_.camera_grab_ms));
    if (!grabbed) {
      Fail(source.name + ": " + grabbed.error().message);
      return;
    }
    if (!grabbed->has_value()) continue;
    robotio::DepthFrame frame = std::move(**grabbed);
    std::lock_guard<std::mutex> lock(mutex_);
    last_frame_host_ns_[index] = HostNanos();
    if (frame.stamp_ns < config_.origin_ns) continue;
    frame.stamp_ns -= config_.origin_ns;
    frame.received_ns -= config_.origin_ns;
    pending_.push_back(std::move(frame));
  }
}

bool DeviceDriver::Cycle(std::int64_t now_ns, bool deadman_held) {
  auto odometry = sources_.base->ReadOdometry();
  if (!odometry) {
    Fail(odometry.error().message);
    return false;
  }
  std::vector<robotio::ImuReading> imu;
  if (sources_.imu != nullptr) {
    auto read = sources_.imu->ReadImu();
    if (!read) {
      Fail(read.error().message);
      return false;
    }
    imu = std::move(*read);
  }
  Rebase(&*odometry, config_.origin_ns);
  Rebase(&imu, config_.origin_ns);
  std::vector<robotio::DepthFrame> frames;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    frames.swap(pending_);
    const std::int64_t host = HostNanos();
    for (std::size_t i = 0; i < last_frame_host_ns_.size() && !error_; ++i) {
      const std::int64_t since = host - std::max(last_frame_host_ns_[i], config_.origin_ns);
      if (since > static_cast<std::int64_t>(config_.camera_silence_ms) * 1'000'000) {
        error_ = sources_.cameras[i].name + ": no depth frame for " +
                 std::to_string(config_.camera_silence_ms) + " ms";
      }
    }
    if (error_) return false;
  }

  mediator_.odometry.Add(*odometry, imu);
  if (recording_ != nullptr) {
    bool ok = true;
    for (const auto& r : *odometry) ok = recording_->AddOdometry(r).ok() && ok;
    for (const auto& r : imu) ok = recording_->AddImu(r).ok() && ok;
    for (const auto& f : frames) ok = recording_->AddDepth(f).ok() && ok;
    if (!ok) ++recording_errors_;
  }
  for (robotio::DepthFrame& frame : frames) {
    const int sensor = frame.sensor_id;
    if (sensor >= 0 && sensor < kMaxKinects) mediator_.latest_depth[sensor].Set(frame);
    mediator_.counters.last_frame_received_ns = frame.received_ns;
    mediator_.frames.Push(CapturedFrame{std::move(frame), std::nullopt, std::nullopt});
  }

  // The planner's command reaches the base only while the mission runs and the operator
  // holds the dead-man switch.
  robotio::VelocityCommand command{now_ns, 0.0, 0.0};
  const auto planned = mediator_.command.Get();
  const bool running = mediator_.control.state() == MissionState::kRunning;
  if (planned && running && deadman_held) {
    command = planned->value;
    command.stamp_ns = now_ns;
    ++commands_passed_;
  } else {
    ++commands_held_back_;
  }
  if (auto sent = sources_.base->Command(command); !sent) {
    Fail(sent.error().message);
    return false;
  }
  mediator_.clock.AdvanceTo(now_ns);
  return true;
}

void DeviceDriver::Run() {
  if (config_.origin_ns == 0) config_.origin_ns = HostNanos();
  std::vector<std::thread> grabbers;
  for (std::size_t i = 0; i < sources_.cameras.size(); ++i) {
    grabbers.emplace_back([this, i] { GrabLoop(i); });
  }
  const auto end_ns = static_cast<std::int64_t>(config_.max_time_s * 1e9);
  while (!mediator_.control.stopping()) {
    auto held = sources_.deadman(std::chrono::milliseconds(config_.cycle_ms));
    if (!held) {
      Fail(held.error().message);
      break;
    }
    const std::int64_t now_ns = HostNanos() - config_.origin_ns;
    if (now_ns >= end_ns) {
      reached_time_limit_ = true;
      break;
    }
    if (!Cycle(now_ns, *held)) break;
  }
  // Whatever ended the loop, the base is stopped first.
  sources_.base->Stop();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_cameras_ = true;
  }
  for (std::thread& t : grabbers) t.join();
  if (const auto error = device_error()) spdlog::error("mission ended: {}", *error);
}

}  // namespace dynamap::app::runtime
