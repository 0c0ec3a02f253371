#include "cli/DeviceRecording.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "cli/CommandSupport.hpp"
#include "cli/Interrupt.hpp"
#include "cli/ProgressLine.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/hardware/MonotonicClock.hpp"
#include "dynamap/robotio/hardware/RecordingDevices.hpp"
#include "dynamap/robotio/hardware/RecordingLoop.hpp"

namespace dynamap::app {

namespace {

namespace hw = robotio::hardware;

const char* const kCommand = "record";

std::string FramesText(const std::vector<std::uint64_t>& frames) {
  std::string text;
  for (const std::uint64_t n : frames) text += (text.empty() ? "" : "+") + std::to_string(n);
  return text.empty() ? "no" : text;
}

// `live`: the recording runs and the dead-man state matters to the driver.
std::string ProgressText(const hw::RecordingProgress& p, double duration_s, bool live) {
  char elapsed[48];
  if (duration_s > 0.0) {
    std::snprintf(elapsed, sizeof elapsed, "%6.1f s / %.1f s", p.elapsed_s, duration_s);
  } else {
    std::snprintf(elapsed, sizeof elapsed, "%6.1f s", p.elapsed_s);
  }
  std::string text = std::string(elapsed) + "  odometry " + std::to_string(p.odometry) + "  gyro " +
                     std::to_string(p.imu) + "  depth " + FramesText(p.frames);
  if (p.dropped_frames > 0) text += " (" + std::to_string(p.dropped_frames) + " dropped)";
  if (!live) return text;
  return text + (p.deadman_held ? "  LB held" : "  LB released: base stopped");
}

std::string EndText(hw::RecordingEnd end) {
  switch (end) {
    case hw::RecordingEnd::kDuration:
      return "the duration was reached";
    case hw::RecordingEnd::kFinishButton:
      return "Start was pressed on the pad";
    case hw::RecordingEnd::kInterrupted:
      return "it was interrupted (Ctrl-C or SIGTERM)";
    case hw::RecordingEnd::kDeviceError:
      return "a device failed";
    case hw::RecordingEnd::kWriteError:
      return "writing failed";
  }
  return "";
}

// `message` ending in a full stop, so a hint can follow it as a sentence.
std::string Sentence(const std::string& message) {
  return !message.empty() && message.back() == '.' ? message : message + ".";
}

}  // namespace

robotio::Rig LoadDeviceRig(const char* command, const DeviceOptions& options) {
  auto rig =
      robotio::LoadRig(options.rig.empty() ? ResourcePath("rigs/two_kinects.yaml") : options.rig);
  if (!rig) FailCommand(command, rig.error().message);
  if (options.width > 0) {
    for (auto& k : rig->kinects) {
      const int height = options.width * k.intrinsics.height / k.intrinsics.width;
      k.intrinsics = k.intrinsics.Scaled(options.width, height);
    }
  }
  return *rig;
}

hw::RecordingDevices OpenRobotDevices(const char* command, const DeviceOptions& options,
                                      const robotio::Rig& rig) {
  hw::DriveDevicesConfig config;
  config.rmp.device = options.rmp_port;
  if (!options.no_imu) {
    config.imu.emplace();
    config.imu->device = options.imu_port;
    config.imu->baud = options.imu_baud;
    config.imu->mount_rpy_deg = {options.imu_rpy_deg[0], options.imu_rpy_deg[1],
                                 options.imu_rpy_deg[2]};
  }
  config.pad.device = options.pad;
  auto devices = hw::OpenDriveDevices(config);
  if (!devices) FailCommand(command, devices.error().message);
  if (options.no_cameras) return std::move(devices).value();

  if (auto opened = hw::OpenRigCameras(rig, options.cameras, &*devices); !opened) {
    // Only recording may do without depth; a mission needs the Kinects.
    const std::string hint = std::string(command) == "record"
                                 ? " Give one --camera per Kinect, in rig order, or --no-cameras "
                                   "to record without depth."
                                 : " Give one --camera per Kinect, in rig order.";
    FailCommand(command, Sentence(opened.error().message) + hint);
  }
  return std::move(devices).value();
}

namespace {

nlohmann::json DeviceReport(const DeviceOptions& options, hw::RecordingDevices& devices,
                            const hw::RecordingLoopResult& result) {
  const hw::RmpLinkStats rmp = devices.base->Stats();
  nlohmann::json report = {
      {"command", "record"},
      {"source", "hardware"},
      {"end", hw::RecordingEndName(result.end)},
      {"error", result.error ? result.error->message : ""},
      {"duration_s", result.totals.elapsed_s},
      {"odometry_readings", result.totals.odometry},
      {"imu_readings", result.totals.imu},
      {"depth_frames", result.totals.frames},
      {"dropped_depth_frames", result.totals.dropped_frames},
      {"rmp",
       {{"device", options.rmp_port},
        {"frames", rmp.frames},
        {"checksum_errors", rmp.checksum_errors},
        {"skipped_bytes", rmp.skipped_bytes},
        {"watchdog_stops", rmp.watchdog_stops},
        {"battery_v", rmp.battery_v ? nlohmann::json(*rmp.battery_v) : nlohmann::json()}}},
      {"pad", options.pad},
      {"cameras", devices.camera_names}};
  if (devices.imu) {
    const hw::XsensLinkStats imu = devices.imu->Stats();
    report["imu"] = {{"device", options.imu_port},
                     {"samples", imu.samples},
                     {"lost_samples", imu.lost_samples},
                     {"checksum_errors", imu.checksum_errors},
                     {"device_errors", imu.device_errors}};
  }
  return report;
}

}  // namespace

void AddDeviceOptions(CLI::App& command, CLI::Option* device_flag, DeviceOptions& options) {
  options.rmp_port = hw::RmpConfig{}.device;
  options.imu_port = hw::XsensImuConfig{}.device;
  options.imu_baud = hw::XsensImuConfig{}.baud;
  options.pad = hw::GamepadConfig{}.device;
  const std::string group = "Real robot (with --device)";
  command.add_option("--rmp-port", options.rmp_port, "Segway RMP serial device")
      ->capture_default_str()
      ->needs(device_flag)
      ->group(group);
  auto* no_imu = command.add_flag("--no-imu", options.no_imu, "Without the gyro (odometry alone for heading)")
                     ->needs(device_flag)
                     ->group(group);
  command.add_option("--imu-port", options.imu_port, "Xsens gyro serial device")
      ->capture_default_str()
      ->needs(device_flag)
      ->excludes(no_imu)
      ->group(group);
  command.add_option("--imu-baud", options.imu_baud, "Xsens gyro baud rate")
      ->capture_default_str()
      ->needs(device_flag)
      ->excludes(no_imu)
      ->group(group);
  command
      .add_option("--imu-rpy-deg", options.imu_rpy_deg,
                  "Gyro mounting roll pitch yaw in the base frame, degrees (180 0 0: upside down)")
      ->expected(3)
      ->needs(device_flag)
      ->excludes(no_imu)
      ->group(group);
  command.add_option("--pad", options.pad, "Gamepad joystick device")
      ->capture_default_str()
      ->needs(device_flag)
      ->group(group);
  auto* no_cameras = command
                         .add_flag("--no-cameras", options.no_cameras,
                                   "Without depth (odometry and gyro only; record only)")
                         ->needs(device_flag)
                         ->group(group);
  command
      .add_option("--camera", options.cameras,
                  "Kinect for each rig entry, in rig order: an OpenNI2 URI, serial:XYZ, a .oni "
                  "file, or N for the N-th camera OpenNI2 lists (default: the only camera, "
                  "for a one-Kinect rig)")
      ->needs(device_flag)
      ->excludes(no_cameras)
      ->group(group);
}

void RunDeviceRecord(const DeviceOptions& options) {
  const robotio::Rig rig = LoadDeviceRig(kCommand, options);
  // Every device must answer before the recording folder is created.
  hw::RecordingDevices devices = OpenRobotDevices(kCommand, options, rig);

  hw::RecordingLoopConfig loop;
  loop.duration_s = options.duration_s;
  loop.origin_ns = hw::MonotonicNanos();
  robotio::RecordingMeta meta;
  meta.source = "hardware";
  meta.duration_s = options.duration_s;
  meta.extra["clock"] = "host monotonic clock, t = 0 at the start of recording";
  meta.extra["host_monotonic_origin_ns"] = std::to_string(loop.origin_ns);
  meta.extra["rmp"] = options.rmp_port;
  meta.extra["imu"] = options.no_imu ? "none" : options.imu_port;
  meta.extra["pad"] = options.pad;
  std::string cameras;
  for (const std::string& name : devices.camera_names)
    cameras += (cameras.empty() ? "" : ", ") + name;
  meta.extra["cameras"] = cameras.empty() ? "none" : cameras;
  char host[256] = {};
  if (::gethostname(host, sizeof host - 1) == 0) meta.extra["host"] = host;
  auto writer = robotio::RecordingWriter::Create(options.out, rig, meta);
  if (!writer) FailCommand(kCommand, writer.error().message);

  std::fprintf(stderr,
               "recording to %s: hold LB and use the sticks to drive; Start on the pad or "
               "Ctrl-C ends the recording\n",
               options.out.c_str());
  hw::RecordingLoopResult result;
  {
    InterruptGuard guard;
    ProgressLine progress("recording");
    result = hw::RunRecordingLoop(
        loop, devices.Sources(), **writer, InterruptGuard::flag(),
        [&](const hw::RecordingProgress& p) {
          const double fraction = options.duration_s > 0.0 ? p.elapsed_s / options.duration_s : 0.0;
          progress.Update(fraction, ProgressText(p, options.duration_s, true));
        });
    progress.Finish(ProgressText(result.totals, options.duration_s, false));
  }
  writer->reset();  // Closes the index files.

  WriteJsonReport(kCommand, DeviceReport(options, devices, result),
                  (std::filesystem::path(options.out) / "report.json").string());
  if (result.error) {
    FailCommand(kCommand, result.error->message +
                              "; driving stopped, and the recording up to "
                              "that point is saved in " +
                              options.out);
  }
  std::fprintf(stderr, "recorded %.1f s into %s; ended because %s\n", result.totals.elapsed_s,
               options.out.c_str(), EndText(result.end).c_str());
}

}  // namespace dynamap::app
