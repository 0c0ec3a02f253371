#include "dynamap/robotio/hardware/RecordingLoop.hpp"

#include <algorithm>
#include <cassert>
#include <chrono>
#include <memory>
#include <mutex>
#include <thread>

#include "RecordingSink.hpp"
#include "dynamap/robotio/hardware/MonotonicClock.hpp"

namespace dynamap::robotio::hardware {
namespace {

using internal::RecordingSink;

constexpr std::int64_t kNsPerMs = 1'000'000;

// One thread per camera, blocked in Grab, so every frame's arrival stamp is taken when it
// arrives rather than when a shared loop comes round to it.
class CameraThreads {
 public:
  CameraThreads(const RecordingLoopConfig& config, const std::vector<RecordingCamera>& cameras,
                RecordingSink& sink)
      : config_(config), sink_(sink) {
    for (const RecordingCamera& camera : cameras) {
      threads_.emplace_back([this, camera] { Run(camera); });
    }
  }
  ~CameraThreads() { Stop(); }
  CameraThreads(const CameraThreads&) = delete;
  CameraThreads& operator=(const CameraThreads&) = delete;

  void Stop() {
    quit_ = true;
    for (std::thread& thread : threads_) {
      if (thread.joinable()) thread.join();
    }
  }
  [[nodiscard]] std::optional<Error> error() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
  }

 private:
  void Fail(const std::string& message) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error_) error_ = Error{message};
  }

  void Run(const RecordingCamera& camera) {
    const std::int64_t silence_ns = std::int64_t{config_.camera_silence_ms} * kNsPerMs;
    std::int64_t last_frame_ns = MonotonicNanos();
    while (!quit_) {
      Expected<std::optional<DepthFrame>> grabbed =
          camera.camera->Grab(std::chrono::milliseconds(config_.camera_grab_ms));
      const std::int64_t now = MonotonicNanos();
      if (!grabbed) {
        Fail(camera.name + ": " + grabbed.error().message);
        return;
      }
      if (!grabbed->has_value()) {
        // Some drivers report an unplugged camera only as frames that stop coming.
        if (now - last_frame_ns > silence_ns) {
          Fail(camera.name + ": no depth frame for " + std::to_string(config_.camera_silence_ms) +
               " ms (USB cable, or the Kinect's 12 V supply?)");
          return;
        }
        continue;
      }
      last_frame_ns = now;
      DepthFrame frame = std::move(**grabbed);
      if (frame.received_ns < config_.origin_ns) continue;
      frame.stamp_ns -= config_.origin_ns;
      frame.received_ns -= config_.origin_ns;
      sink_.AddFrame(std::move(frame));
    }
  }

  const RecordingLoopConfig& config_;
  RecordingSink& sink_;
  std::atomic<bool> quit_{false};
  mutable std::mutex mutex_;
  std::optional<Error> error_;
  std::vector<std::thread> threads_;  // Last: the threads use the members above.
};

// Readings from before the recording's origin are dropped, the rest shifted to it.
template <typename Reading>
std::vector<Reading> SinceOrigin(std::vector<Reading> readings, std::int64_t origin_ns) {
  std::vector<Reading> kept;
  kept.reserve(readings.size());
  for (Reading& r : readings) {
    if (r.stamp_ns < origin_ns) continue;
    r.stamp_ns -= origin_ns;
    kept.push_back(r);
  }
  return kept;
}

void Fill(RecordingProgress& progress, const internal::SinkCounts& counts, std::size_t cameras) {
  progress.odometry = counts.odometry;
  progress.imu = counts.imu;
  progress.frames = counts.frames;
  progress.frames.resize(std::max(progress.frames.size(), cameras), 0);
  progress.dropped_frames = counts.dropped_frames;
}

}  // namespace

const char* RecordingEndName(RecordingEnd end) {
  switch (end) {
    case RecordingEnd::kDuration:
      return "duration";
    case RecordingEnd::kFinishButton:
      return "finish_button";
    case RecordingEnd::kInterrupted:
      return "interrupted";
    case RecordingEnd::kDeviceError:
      return "device_error";
    case RecordingEnd::kWriteError:
      return "write_error";
  }
  return "unknown";
}

RecordingLoopResult RunRecordingLoop(
    const RecordingLoopConfig& config, const RecordingSources& sources, RecordingWriter& writer,
    const std::atomic<bool>& interrupt,
    const std::function<void(const RecordingProgress&)>& on_progress) {
  assert(sources.base != nullptr && sources.teleop != nullptr);
  RecordingSink sink(writer, static_cast<int>(sources.cameras.size()), config.max_queued_frames);
  CameraThreads cameras(config, sources.cameras, sink);
  const auto duration_ns = static_cast<std::int64_t>(config.duration_s * 1e9);

  RecordingLoopResult result;
  RecordingProgress progress;
  std::optional<RecordingEnd> end;
  auto fail = [&](RecordingEnd why, const Error& error) {
    end = why;
    result.error = error;
  };
  while (!end) {
    const std::int64_t now = MonotonicNanos();
    progress.elapsed_s = static_cast<double>(now - config.origin_ns) * 1e-9;
    if (interrupt.load()) {
      end = RecordingEnd::kInterrupted;
      break;
    }
    if (duration_ns > 0 && now - config.origin_ns >= duration_ns) {
      end = RecordingEnd::kDuration;
      break;
    }
    Expected<TeleopState> state =
        sources.teleop->Update(std::chrono::milliseconds(config.teleop_wait_ms));
    if (!state) {
      fail(RecordingEnd::kDeviceError, state.error());
      break;
    }
    progress.deadman_held = state->deadman_held;
    if (state->finish_requested) {
      end = RecordingEnd::kFinishButton;
      break;
    }
    if (Status sent = sources.base->Command(state->command); !sent) {
      fail(RecordingEnd::kDeviceError, sent.error());
      break;
    }
    progress.command = state->command;
    Expected<std::vector<OdometryReading>> odometry = sources.base->ReadOdometry();
    if (!odometry) {
      fail(RecordingEnd::kDeviceError, odometry.error());
      break;
    }
    sink.AddOdometry(SinceOrigin(std::move(odometry).value(), config.origin_ns));
    if (sources.imu != nullptr) {
      Expected<std::vector<ImuReading>> imu = sources.imu->ReadImu();
      if (!imu) {
        fail(RecordingEnd::kDeviceError, imu.error());
        break;
      }
      sink.AddImu(SinceOrigin(std::move(imu).value(), config.origin_ns));
    }
    if (std::optional<Error> error = cameras.error()) {
      fail(RecordingEnd::kDeviceError, *error);
      break;
    }
    if (std::optional<Error> error = sink.error()) {
      fail(RecordingEnd::kWriteError, *error);
      break;
    }
    Fill(progress, sink.counts(), sources.cameras.size());
    if (on_progress) on_progress(progress);
  }

  // Stop first, then collect: the base must not wait for the disk.
  sources.base->Stop();
  cameras.Stop();
  // What arrived after the last cycle still belongs to the recording. A driver that already
  // failed answers with its Error again, which changes nothing here.
  if (Expected<std::vector<OdometryReading>> rest = sources.base->ReadOdometry(); rest.ok()) {
    sink.AddOdometry(SinceOrigin(std::move(rest).value(), config.origin_ns));
  }
  if (sources.imu != nullptr) {
    if (Expected<std::vector<ImuReading>> rest = sources.imu->ReadImu(); rest.ok()) {
      sink.AddImu(SinceOrigin(std::move(rest).value(), config.origin_ns));
    }
  }
  if (std::optional<Error> write_error = sink.Close()) {
    if (!result.error) {
      end = RecordingEnd::kWriteError;
      result.error = write_error;
    } else if (end != RecordingEnd::kWriteError) {
      result.error->message += "; writing the recording also failed: " + write_error->message;
    }
  }
  result.end = *end;
  progress.elapsed_s = static_cast<double>(MonotonicNanos() - config.origin_ns) * 1e-9;
  progress.command = VelocityCommand{};
  Fill(progress, sink.counts(), sources.cameras.size());
  result.totals = progress;
  return result;
}

}  // namespace dynamap::robotio::hardware
