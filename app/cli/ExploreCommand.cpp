#include "cli/ExploreCommand.hpp"

#include <spdlog/spdlog.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <memory>
#include <optional>
#include <thread>
#include <vector>

#include "cli/CommandSupport.hpp"
#include "cli/DeviceRecording.hpp"
#include "cli/FinalMap.hpp"
#include "cli/Interrupt.hpp"
#include "cli/ProgressLine.hpp"
#include "dynamap/app/runtime/MissionRuntime.hpp"
#include "dynamap/app/runtime/RobotSources.hpp"
#include "dynamap/mapping/MappingConfig.hpp"
#include "dynamap/mapping/SlamLoop.hpp"
#include "dynamap/planning/PlanningConfig.hpp"

namespace dynamap::app {

namespace {

struct ExploreOptions {
  std::string world = ResourcePath("worlds/office.yaml");
  std::string rig;  // "" = resources/rigs/two_kinects.yaml; with --replay the recorded rig.
  std::string robot = ResourcePath("robots/segway_rmp50.yaml");
  std::string planning;  // Planning settings over the defaults; "" = defaults.
  std::string slam;      // SLAM settings over the defaults (--poses slam); "" = defaults.
  std::string mapping;   // Map settings over the defaults; "" = defaults.
  std::string out;
  std::uint64_t seed = 1;
  double max_time_s = 1200.0;
  double speed = 0.0;
  std::string targets = "default";
  std::string poses = "slam";
  int kinect_width = 320;
  bool record = false;
  bool final_map = false;  // Map the recording again along the loop-closed trajectory.
  bool headless = false;
  bool device = false;          // The real robot instead of the simulator.
  std::string replay;           // A recording replayed through the mission instead.
  double area_m = runtime::MissionConfig{}.area_m;
  DeviceOptions device_options;
};

std::string TimestampedRunDir() {
  const std::time_t now = std::time(nullptr);
  char name[64];
  std::strftime(name, sizeof(name), "runs/explore-%Y%m%d-%H%M%S", std::localtime(&now));
  return name;
}

const char* TargetText(const runtime::MissionSnapshot& s) {
  if (!s.has_goal) return s.exploration_done ? "done" : "looking around";
  return planning::TargetKindName(s.target_kind);
}

runtime::MissionConfig ConfigFor(const ExploreOptions& options) {
  runtime::MissionConfig config;
  config.world_file = options.world;
  config.rig_file = options.rig;
  config.recording_dir = options.replay;
  config.robot_file = options.robot;
  config.out_dir = options.out.empty() ? TimestampedRunDir() : options.out;
  config.seed = options.seed;
  config.max_time_s = options.max_time_s;
  config.speed = options.speed;
  config.kinect_width = options.kinect_width;
  config.kinect_height = options.kinect_width * 3 / 4;
  config.record = options.record || (options.final_map && options.replay.empty());
  config.area_m = options.area_m;
  config.poses = options.poses == "odometry"      ? runtime::PoseSource::kOdometry
                 : options.poses == "groundtruth" ? runtime::PoseSource::kGroundTruth
                                                  : runtime::PoseSource::kSlam;
  if (!options.planning.empty()) {
    auto planning = planning::LoadPlanningConfig(options.planning);
    if (!planning) FailCommand("explore", planning.error().message);
    config.planning = *planning;
  }
  if (!options.mapping.empty()) {
    auto loaded = mapping::LoadMappingConfig(options.mapping);
    if (!loaded) FailCommand("explore", loaded.error().message);
    config.mapping = *loaded;
  }
  if (!options.slam.empty()) {
    auto slam = mapping::LoadSlamConfig(options.slam);
    if (!slam) FailCommand("explore", slam.error().message);
    config.slam = *slam;
  }
  // "default" keeps the planning configuration's strategy (a --planning file's, or the
  // built-in one).
  if (options.targets != "default") config.planning.targets.strategy = options.targets;
  return config;
}

// A mission can finish with frontier regions it passed over: say so, with where they are.
void PrintFrontiersLeft(const runtime::MissionReport& report) {
  const auto print = [](const char* why, const std::vector<Eigen::Vector2d>& regions) {
    if (regions.empty()) return;
    std::printf("%zu frontier region%s %s, left unexplored at", regions.size(),
                regions.size() == 1 ? "" : "s", why);
    for (const Eigen::Vector2d& p : regions) std::printf(" (%.1f, %.1f)", p.x(), p.y());
    std::printf(" m (map frame; crosses in map2d.png)\n");
  };
  print("no viewpoint reaches", report.unreachable_frontiers);
  print("blacklisted after failed tries", report.blacklisted_frontiers);
}

FinalMapRequest FinalMapRequestFor(const ExploreOptions& options,
                                   const runtime::MissionConfig& config) {
  const bool replayed = !options.replay.empty();
  return {config.out_dir, replayed ? options.replay : config.out_dir + "/recording",
          options.mapping, replayed ? options.rig : ""};
}

void Run(const ExploreOptions& options) {
  const runtime::MissionConfig config = ConfigFor(options);
  std::optional<robotio::hardware::RecordingDevices> devices;
  auto pad_state = std::make_shared<runtime::PadState>();
  robotio::Expected<std::unique_ptr<runtime::MissionRuntime>> runtime = [&] {
    // The simulator, or the recording named by config.recording_dir.
    if (!options.device) return runtime::MissionRuntime::Create(config);
    if (options.device_options.no_cameras) {
      FailCommand("explore", "--no-cameras: a mission maps and plans with the Kinects");
    }
    DeviceOptions device_options = options.device_options;
    device_options.rig = options.rig;
    device_options.width = options.kinect_width;
    const robotio::Rig rig = LoadDeviceRig("explore", device_options);
    devices = OpenRobotDevices("explore", device_options, rig);
    return runtime::MissionRuntime::CreateOnDevices(config, runtime::SourcesFromRobot(*devices, pad_state));
  }();
  if (!runtime) FailCommand("explore", runtime.error().message);

  if (options.device) {
    spdlog::info("exploring with the robot (poses {}), results in {}: the base moves only "
                 "while LB is held; Start on the pad or Ctrl-C ends the mission",
                 options.poses, config.out_dir);
  } else {
    spdlog::info("exploring {} (seed {}, poses {}, {}), results in {}",
                 options.replay.empty() ? config.world_file : "the recording " + options.replay,
                 config.seed, options.poses,
                 config.speed > 0 ? std::to_string(config.speed) + "x real time"
                                  : std::string("as fast as the machine allows"),
                 config.out_dir);
  }
  const auto wall_start = std::chrono::steady_clock::now();
  const InterruptGuard interrupt;
  (*runtime)->Start();
  ProgressLine progress("exploring");
  while (!(*runtime)->finished()) {
    const bool finish = pad_state->finish;
    if (InterruptGuard::requested() || finish) {
      spdlog::info("{}: stopping the mission and saving its results{}",
                   finish ? "Start pressed" : "interrupted",
                   finish ? "" : " (interrupt again to quit without them)");
      (*runtime)->Stop();
      break;
    }
    const runtime::MissionSnapshot s = (*runtime)->Snapshot();
    if (s.state == runtime::MissionState::kStopping) break;
    double known_m2 = 0.0;
    if (s.grid) {
      for (const auto cell : s.grid->cells) {
        if (cell == planning::CellState::kNavigable) known_m2 += 1.0;
      }
      known_m2 *= s.grid->resolution_m * s.grid->resolution_m;
    }
    char loops[32] = "";
    // Times closures moved the pose so far (only when they are made as the robot goes).
    if (config.poses == runtime::PoseSource::kSlam && config.slam.loop_closure.enabled &&
        config.slam.loop_closure.correct_while_running) {
      std::snprintf(loops, sizeof(loops), "  loops %lld", static_cast<long long>(s.loop_closures));
    }
    char detail[300];
    std::snprintf(detail, sizeof(detail),
                  "t %6.1f s  known floor %6.1f m2  driven %6.1f m  v %4.2f w %5.2f  stops %lld%s  %s%s",
                  s.sim_time_s, known_m2, s.distance_m, s.command.v, s.command.omega,
                  static_cast<long long>(s.guard_stops), loops, TargetText(s),
                  options.device && !pad_state->held ? "  (LB released: base held)" : "");
    progress.Update(s.sim_time_s / (*runtime)->config().max_time_s, detail);
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
  }
  (*runtime)->Wait();
  auto report = (*runtime)->Finish();
  if (!report) FailCommand("explore", report.error().message);
  if (options.device) {
    char summary[300];
    std::snprintf(summary, sizeof(summary),
                  "%s after %.0f s: driven %.1f m (estimated), %lld frames mapped, %lld guard stops",
                  report->completed ? "complete" : "stopped", report->mission_time_s,
                  report->path_length_m, static_cast<long long>(report->frames_processed),
                  static_cast<long long>(report->guard_stops));
    progress.Finish(summary);
    PrintFrontiersLeft(*report);
    if (options.final_map) BuildFinalMap(FinalMapRequestFor(options, config));
    std::printf("results: %s (report.json, map2d.png, map.ot, static.bt, dynamic.bt, ...)\n",
                config.out_dir.c_str());
    if (const auto error = (*runtime)->device_error()) {
      FailCommand("explore", *error + "; the base was stopped, and the maps so far are saved in " +
                                 config.out_dir);
    }
    return;
  }
  const double wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  char summary[400];
  std::snprintf(summary, sizeof(summary),
                "%s in %.0f s simulated (%.0f s wall): explored %.1f%%, surfaces %.1f%%, path "
                "%.1f m, ATE %.3f m, SA %.3f, DA %.3f, collisions %lld",
                report->completed ? "complete" : "stopped", report->mission_time_s, wall_s,
                100.0 * report->explored_free_fraction, 100.0 * report->surface_coverage,
                report->path_length_m, report->ate_rmse_m, report->static_accuracy,
                report->dynamic_accuracy, static_cast<long long>(report->collisions));
  progress.Finish(summary);
  PrintFrontiersLeft(*report);
  if (options.final_map) BuildFinalMap(FinalMapRequestFor(options, config));
  std::printf("results: %s (report.json, map2d.png, map.ot, static.bt, dynamic.bt, ...)\n",
              config.out_dir.c_str());
}

}  // namespace

void RegisterExploreCommand(CLI::App& app) {
  auto options = std::make_shared<ExploreOptions>();
  CLI::App* cmd = app.add_subcommand(
      "explore", "Explore autonomously, a simulated world or with the real robot (--device): "
                 "SLAM, dual static/dynamic map, target planning, D* Lite, collision guard; "
                 "writes maps and report.json");
  auto* world = cmd->add_option("--world", options->world, "World file")->check(CLI::ExistingFile);
  auto* device = cmd->add_flag(
      "--device", options->device,
      "Explore with the real robot (Segway RMP, Xsens gyro, Kinects) instead of the simulator, "
      "in real time; the base moves only while the pad's LB is held (docs/HARDWARE.md)");
  world->excludes(device);
  auto* replay = cmd->add_option("--replay", options->replay,
                                 "Replay a recording through the mission (SLAM, maps, planning; "
                                 "the robot is not steered) instead of simulating; scored "
                                 "against its world and ground truth when it was simulated")
                     ->check(CLI::ExistingDirectory)
                     ->excludes(world)
                     ->excludes(device);
  cmd->add_option("--rig", options->rig,
                  "Kinect rig file (default resources/rigs/two_kinects.yaml; with --replay its "
                  "poses and latencies replace the recorded ones)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--robot", options->robot, "Robot file")->check(CLI::ExistingFile);
  cmd->add_option("--planning", options->planning,
                  "Planning settings (YAML, the keys of planning::PlanningConfig) over the "
                  "defaults, e.g. 'targets: {frontiers_first: true}'")
      ->check(CLI::ExistingFile);
  cmd->add_option("--slam", options->slam,
                  "SLAM settings (YAML, the keys of mapping::SlamConfig) over the defaults, "
                  "as for dynamap map --slam")
      ->check(CLI::ExistingFile);
  cmd->add_option("--mapping", options->mapping,
                  "Map settings (YAML under 'mapping:' with the keys of mapping::MappingConfig, "
                  "e.g. 'edge_clearance_voxels: 1') over the defaults, as for dynamap map")
      ->check(CLI::ExistingFile);
  cmd->add_option("--out", options->out, "Output folder (default: a new runs/explore-* folder)");
  cmd->add_option("--seed", options->seed, "Simulator seed")->excludes(device)->excludes(replay);
  cmd->add_option("--max-time", options->max_time_s, "Seconds of mission time (simulated, or real with --device) before the mission ends")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--speed", options->speed,
                  "Simulated seconds per wall second; 0 = as fast as the machine allows "
                  "without dropping frames")
      ->check(CLI::NonNegativeNumber)
      ->excludes(device);
  cmd->add_option("--targets", options->targets,
                  "Target planner: default (the planning configuration's), gain (gain over "
                  "path cost), tour (first stop of the shortest tour through all targets) or "
                  "nearest-frontier (Yamauchi's baseline)")
      ->check(CLI::IsMember({"default", "gain", "tour", "nearest-frontier"}));
  cmd->add_option("--poses", options->poses, "Where frames are placed from")
      ->check(CLI::IsMember({"slam", "odometry", "groundtruth"}));
  cmd->add_option("--kinect-width", options->kinect_width,
                  "Simulated Kinect image width in px (height = 3/4 of it; 640 = full Kinect)")
      ->check(CLI::Range(80, 640));
  cmd->add_flag("--record", options->record, "Also write the run as a recording (recording/)")
      ->excludes(replay);
  cmd->add_flag("--final-map", options->final_map,
                "After the mission, map its recording again along the loop-closed "
                "trajectory into final_map/ (as dynamap map --trajectory; records the run "
                "unless it is a --replay)");
  cmd->add_flag("--headless", options->headless,
                "Run without a window (explore always runs in the terminal; the GUI has its "
                "own Mission workspace)");
  AddDeviceOptions(*cmd, device, options->device_options);
  cmd->add_option("--area", options->area_m,
                  "With --device: side of the square area around the start that the 2D map "
                  "covers, m")
      ->check(CLI::Range(2.0, 500.0))
      ->needs(device);
  cmd->callback([options] { Run(*options); });
}

}  // namespace dynamap::app
