#include "cli/RecordCommand.hpp"

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "cli/CommandSupport.hpp"
#include "cli/DeviceRecording.hpp"
#include "cli/ProgressLine.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app {

namespace {

namespace sim = robotio::sim;

constexpr double kChunkS = 0.1;  // s of simulated time handed to the writer at once.

struct RecordOptions {
  std::string world;
  std::string teleop;       // A scripted drive replacing the world's ("" = the world's).
  std::string rig;
  std::string robot;
  std::string out;
  double duration_s = 0.0;  // 0: the world's duration_s.
  std::uint64_t seed = 1;
  int width = 0;            // 0: the rig's resolution.
  bool device = false;      // Record the real robot instead of the simulator.
  DeviceOptions device_options;
};

// Writes simulator output on its own thread so PNG encoding overlaps the rendering.
class BackgroundWriter {
 public:
  explicit BackgroundWriter(std::unique_ptr<robotio::RecordingWriter> writer)
      : writer_(std::move(writer)), thread_([this] { Run(); }) {}
  ~BackgroundWriter() { Close(); }

  // Blocks while too much is queued, so memory stays bounded.
  void Push(sim::SimOutput output) {
    std::unique_lock<std::mutex> lock(mutex_);
    space_.wait(lock, [this] { return queue_.size() < 4 || !error_.empty(); });
    queue_.push_back(std::move(output));
    ready_.notify_one();
  }
  // Waits until everything is written; returns the first error, empty if none.
  std::string Close() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      closing_ = true;
      ready_.notify_one();
    }
    if (thread_.joinable()) thread_.join();
    return error_;
  }
  std::string error() {
    std::lock_guard<std::mutex> lock(mutex_);
    return error_;
  }

 private:
  void Run() {
    for (;;) {
      sim::SimOutput output;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        ready_.wait(lock, [this] { return !queue_.empty() || closing_; });
        if (queue_.empty()) return;
        output = std::move(queue_.front());
        queue_.pop_front();
        space_.notify_one();
      }
      const std::string error = Write(output);
      if (!error.empty()) {
        std::lock_guard<std::mutex> lock(mutex_);
        error_ = error;
        queue_.clear();
        space_.notify_all();
        return;
      }
    }
  }

  std::string Write(const sim::SimOutput& output) {
    for (const auto& r : output.odometry) {
      if (auto s = writer_->AddOdometry(r); !s) return s.error().message;
    }
    for (const auto& r : output.imu) {
      if (auto s = writer_->AddImu(r); !s) return s.error().message;
    }
    for (const auto& p : output.ground_truth) {
      if (auto s = writer_->AddGroundTruth(p); !s) return s.error().message;
    }
    for (const auto& f : output.frames) {
      if (auto s = writer_->AddLabels(f.labels, f.depth.received_ns); !s) return s.error().message;
      if (auto s = writer_->AddDepth(f.depth); !s) return s.error().message;
    }
    return {};
  }

  std::unique_ptr<robotio::RecordingWriter> writer_;
  std::mutex mutex_;
  std::condition_variable ready_;
  std::condition_variable space_;
  std::deque<sim::SimOutput> queue_;
  bool closing_ = false;
  std::string error_;
  std::thread thread_;
};

void RunRecord(const RecordOptions& options) {
  const std::string command = "record";
  auto world = sim::LoadWorld(options.world);
  if (!world) FailCommand(command, world.error().message);
  auto rig = robotio::LoadRig(options.rig.empty() ? ResourcePath("rigs/two_kinects.yaml")
                                                  : options.rig);
  if (!rig) FailCommand(command, rig.error().message);
  auto robot = sim::LoadRobotConfig(options.robot.empty()
                                        ? ResourcePath("robots/segway_rmp50.yaml")
                                        : options.robot);
  if (!robot) FailCommand(command, robot.error().message);
  if (options.width > 0) {
    for (auto& k : rig->kinects) {
      const int height = options.width * k.intrinsics.height / k.intrinsics.width;
      k.intrinsics = k.intrinsics.Scaled(options.width, height);
    }
  }
  if (!options.teleop.empty()) {
    auto teleop = sim::LoadTeleop(options.teleop);
    if (!teleop) FailCommand(command, teleop.error().message);
    world->teleop = *teleop;
    // The drive, then 1 s standing, unless --duration says otherwise.
    double drive_s = 1.0;
    for (const auto& segment : world->teleop) drive_s += segment.duration_s;
    world->duration_s = drive_s;
  }
  // Labels follow what stands at the end of *this* run.
  if (options.duration_s > 0.0) world->duration_s = options.duration_s;
  const double duration = world->duration_s;

  robotio::RecordingMeta meta;
  meta.world = std::filesystem::absolute(options.world).string();
  meta.seed = options.seed;
  meta.duration_s = duration;
  meta.extra["world_name"] = world->name;
  if (!options.teleop.empty()) meta.extra["teleop"] = std::filesystem::absolute(options.teleop).string();
  meta.extra["robot"] = robot->name;
  meta.extra["ground_truth_frame"] = "map (origin and heading = robot start pose)";
  auto writer = robotio::RecordingWriter::Create(options.out, *rig, meta);
  if (!writer) FailCommand(command, writer.error().message);
  BackgroundWriter background(std::move(writer).value());

  sim::SimulatorConfig config;
  config.seed = options.seed;
  sim::Simulator simulator(*world, *robot, *rig, config);
  ProgressLine progress("recording");
  const auto wall_start = std::chrono::steady_clock::now();
  const std::int64_t end_ns = robotio::SecondsToNanos(duration);
  nlohmann::json collisions = nlohmann::json::array();
  int frames = 0;
  // Command changes fall on teleop segment boundaries, not just on chunk ends.
  std::vector<std::int64_t> boundaries;
  double t = 0.0;
  for (const auto& segment : world->teleop) boundaries.push_back(robotio::SecondsToNanos(t += segment.duration_s));
  while (simulator.now_ns() < end_ns) {
    const std::int64_t now = simulator.now_ns();
    std::int64_t next = std::min(end_ns, now + robotio::SecondsToNanos(kChunkS));
    for (const std::int64_t b : boundaries) {
      if (b > now && b < next) next = b;
    }
    const auto [v, omega] = sim::TeleopCommandAt(*world, robotio::NanosToSeconds(now));
    simulator.SetCommand({now, v, omega});
    sim::SimOutput output = simulator.AdvanceTo(next);
    frames += static_cast<int>(output.frames.size());
    for (const auto& c : output.collisions) {
      collisions.push_back({{"t_s", robotio::NanosToSeconds(c.stamp_ns)},
                            {"object", c.object_id},
                            {"pose", {c.pose.x, c.pose.y, c.pose.theta}}});
      std::fprintf(stderr, "\ncollision at %.2f s with '%s'\n", robotio::NanosToSeconds(c.stamp_ns),
                   c.object_id.c_str());
    }
    background.Push(std::move(output));
    if (!background.error().empty()) FailCommand(command, background.error());
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    const double sim_s = robotio::NanosToSeconds(simulator.now_ns());
    char detail[96];
    std::snprintf(detail, sizeof(detail), "%5.1f s / %.1f s  %d frames  %.2fx real time", sim_s,
                  duration, frames, wall > 0.0 ? sim_s / wall : 0.0);
    progress.Update(sim_s / duration, detail);
  }
  if (const std::string error = background.Close(); !error.empty()) FailCommand(command, error);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  char detail[96];
  std::snprintf(detail, sizeof(detail), "%.1f s simulated in %.1f s (%.2fx real time), %d frames",
                duration, wall, duration / wall, frames);
  progress.Finish(detail);

  const robotio::Pose2D end_pose = simulator.TruePose();
  nlohmann::json report = {
      {"command", "record"},
      {"world", meta.world},
      {"seed", options.seed},
      {"duration_s", duration},
      {"depth_frames", frames},
      {"kinects", rig->kinects.size()},
      {"wall_time_s", wall},
      {"real_time_factor", duration / wall},
      {"collisions", collisions.size()},
      {"collision_events", collisions},
      {"end_pose_map", {end_pose.x, end_pose.y, end_pose.theta}}};
  WriteJsonReport(command, report, (std::filesystem::path(options.out) / "report.json").string());
}

}  // namespace

void RegisterRecordCommand(CLI::App& app) {
  auto options = std::make_shared<RecordOptions>();
  CLI::App* record = app.add_subcommand(
      "record", "Write a recording: the simulator driven along a world's scripted path, with "
                "ground truth (--world), or the real robot driven with the gamepad (--device)");
  auto* world = record->add_option("--world", options->world, "World or scenario file (YAML)");
  auto* device = record->add_flag(
      "--device", options->device,
      "Record the real robot (Segway RMP, Xsens gyro, Kinects) driven with the gamepad: hold LB "
      "to drive, Start or Ctrl-C ends (docs/HARDWARE.md)");
  world->excludes(device);
  record->add_option("--teleop", options->teleop,
                     "Scripted drive (YAML with a teleop: list, e.g. resources/tours/"
                     "office_tour.yaml) instead of the world's; the duration follows it")
      ->check(CLI::ExistingFile)
      ->needs(world);
  record->add_option("--rig", options->rig, "Rig file (default resources/rigs/two_kinects.yaml)");
  record->add_option("--robot", options->robot,
                     "Robot file (default resources/robots/segway_rmp50.yaml)")
      ->excludes(device);
  record->add_option("--duration", options->duration_s,
                     "Seconds to record (default: the world's duration_s; with --device, until "
                     "Start or Ctrl-C)")
      ->check(CLI::Range(0.01, 1e5));
  record->add_option("--seed", options->seed, "Random seed (same seed, same recording)")
      ->excludes(device);
  record->add_option("--width", options->width, "Depth image width in px (height follows; default: the rig's)")
      ->check(CLI::Range(16, 4096));
  record->add_option("--out", options->out, "New recording folder")->required();
  AddDeviceOptions(*record, device, options->device_options);
  record->callback([options] {
    if (options->device) {
      DeviceOptions device_options = options->device_options;
      device_options.rig = options->rig;
      device_options.out = options->out;
      device_options.duration_s = options->duration_s;
      device_options.width = options->width;
      RunDeviceRecord(device_options);
      return;
    }
    if (options->world.empty()) {
      FailCommand("record", "say what to record: --world FILE (the simulator) or --device (the "
                            "real robot)");
    }
    RunRecord(*options);
  });
}

}  // namespace dynamap::app
