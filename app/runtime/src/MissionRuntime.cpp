#include "dynamap/app/runtime/MissionRuntime.hpp"

#include <spdlog/spdlog.h>

#include "Percentile.hpp"

#include <algorithm>
#include <optional>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "dynamap/app/runtime/ControlWorker.hpp"
#include "dynamap/app/runtime/MappingWorker.hpp"
#include "dynamap/app/runtime/Mediator.hpp"
#include "dynamap/app/runtime/MissionEvaluation.hpp"
#include "dynamap/app/runtime/MissionOutputs.hpp"
#include "dynamap/app/runtime/PlanningWorker.hpp"
#include "dynamap/app/runtime/DeviceDriver.hpp"
#include "dynamap/app/runtime/RecordingDriver.hpp"
#include "dynamap/app/runtime/SimulationDriver.hpp"
#include "dynamap/mapping/MapExport.hpp"
#include "dynamap/mapping/MapFiles.hpp"
#include "dynamap/mapping/TrajectoryEvaluation.hpp"
#include "dynamap/robotio/AtomicFile.hpp"
#include "dynamap/robotio/FloorBlindZone.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"
#include "dynamap/robotio/sim/StaticSurfaces.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app::runtime {

namespace fs = std::filesystem;

namespace {

// The projected grid covers the world's floor (in the map frame) plus a margin.
planning::GridMap AreaFor(const robotio::sim::World& world, double resolution_m) {
  double min_x = 1e9, min_y = 1e9, max_x = -1e9, max_y = -1e9;
  for (double x : {world.floor_min.x(), world.floor_max.x()}) {
    for (double y : {world.floor_min.y(), world.floor_max.y()}) {
      const robotio::Pose2D p = world.ToMap({x, y, 0.0});
      min_x = std::min(min_x, p.x);
      max_x = std::max(max_x, p.x);
      min_y = std::min(min_y, p.y);
      max_y = std::max(max_y, p.y);
    }
  }
  constexpr double kMarginM = 1.0;
  planning::GridMap area(static_cast<int>(std::ceil((max_x - min_x + 2 * kMarginM) / resolution_m)),
                         static_cast<int>(std::ceil((max_y - min_y + 2 * kMarginM) / resolution_m)),
                         resolution_m);
  area.origin_x_m = min_x - kMarginM;
  area.origin_y_m = min_y - kMarginM;
  return area;
}

// Without a world: a square of side `side_m` centred on the start (the map frame's origin).
planning::GridMap SquareArea(double side_m, double resolution_m) {
  const int cells = static_cast<int>(std::ceil(side_m / resolution_m));
  planning::GridMap area(cells, cells, resolution_m);
  area.origin_x_m = -0.5 * side_m;
  area.origin_y_m = -0.5 * side_m;
  return area;
}

std::vector<robotio::Pose2D> ToPoses(const robotio::Trajectory& trajectory) {
  std::vector<robotio::Pose2D> poses;
  for (const auto& p : trajectory) poses.push_back(robotio::Pose2D::FromIsometry(p.pose));
  return poses;
}

}  // namespace

MissionRuntime::MissionRuntime(MissionConfig config, std::optional<robotio::sim::World> world)
    : config_(std::move(config)), world_(std::move(world)) {}

MissionRuntime::~MissionRuntime() {
  if (!threads_.empty() && !joined_) {
    Stop();
    Wait();
  }
}

robotio::Expected<std::unique_ptr<MissionRuntime>> MissionRuntime::Prepare(
    MissionConfig config, std::optional<robotio::sim::World> world,
    std::optional<robotio::Rig> recorded_rig) {
  if (config.rig_file.empty() && !recorded_rig) {
    config.rig_file = std::string(DYNAMAP_RESOURCES_DIR) + "/rigs/two_kinects.yaml";
  }
  if (config.robot_file.empty()) {
    config.robot_file = std::string(DYNAMAP_RESOURCES_DIR) + "/robots/segway_rmp50.yaml";
  }
  robotio::Expected<robotio::Rig> rig =
      recorded_rig ? robotio::Expected<robotio::Rig>(*recorded_rig) : robotio::LoadRig(config.rig_file);
  if (!rig) return rig.error();
  auto robot = robotio::sim::LoadRobotConfig(config.robot_file);
  if (!robot) return robot.error();
  if (auto ok = mapping::ValidateMappingConfig(config.mapping, "mapping settings"); !ok) {
    return ok.error();
  }
  std::error_code ec;
  // Two missions' files never mix: a folder holding an earlier run's results is refused
  // before anything in it is touched.
  for (const char* earlier : {"report.json", "map.ot", "recording"}) {
    if (fs::exists(fs::path(config.out_dir) / earlier, ec)) {
      return robotio::Error{config.out_dir + ": already holds a mission's results (" + earlier +
                            "); give a new output folder"};
    }
  }
  fs::create_directories(config.out_dir, ec);
  if (ec) return robotio::Error{config.out_dir + ": cannot create the output folder"};

  if (recorded_rig) {  // The images are as recorded.
    config.kinect_width = rig->kinects.empty() ? 0 : rig->kinects[0].intrinsics.width;
    config.kinect_height = rig->kinects.empty() ? 0 : rig->kinects[0].intrinsics.height;
  } else {
    for (robotio::KinectMount& mount : rig->kinects) {
      mount.intrinsics = mount.intrinsics.Scaled(config.kinect_width, config.kinect_height);
    }
  }
  // What stands at the end is static ground truth.
  if (world) world->duration_s = config.max_time_s;
  std::unique_ptr<MissionRuntime> runtime(new MissionRuntime(config, std::move(world)));
  runtime->rig_ = *rig;
  runtime->robot_ = *robot;
  runtime->footprint_radius_m_ = robot->footprint_radius_m;

  mapping::MotionModelConfig motion;
  motion.track_width_m = robot->track_width_m;
  runtime->mediator_ = std::make_unique<Mediator>(config.speed, motion);
  if (config.record) {
    robotio::RecordingMeta meta;
    meta.source = runtime->world_ ? "simulator" : "hardware";
    // Absolute, as `dynamap record` writes it: `dynamap map` scores the recording against
    // its world from whatever folder it is run in.
    if (!config.world_file.empty()) {
      meta.world = std::filesystem::absolute(config.world_file).string();
    }
    meta.seed = config.seed;
    meta.duration_s = config.max_time_s;
    auto writer = robotio::RecordingWriter::Create(config.out_dir + "/recording", *rig, meta);
    if (!writer) return writer.error();
    runtime->recording_ = std::move(*writer);
  }
  return runtime;
}

robotio::Expected<std::unique_ptr<MissionRuntime>> MissionRuntime::Create(MissionConfig config) {
  if (!config.recording_dir.empty()) {
    const std::string dir = config.recording_dir;
    return CreateFromRecording(std::move(config), dir);
  }
  auto world = robotio::sim::LoadWorld(config.world_file);
  if (!world) return world.error();
  auto prepared = Prepare(std::move(config), std::move(*world), std::nullopt);
  if (!prepared) return prepared.error();
  std::unique_ptr<MissionRuntime> runtime = std::move(*prepared);
  const MissionConfig& c = runtime->config_;
  robotio::sim::SimulatorConfig sim_config;
  sim_config.seed = c.seed;
  auto simulator = std::make_unique<robotio::sim::Simulator>(*runtime->world_, runtime->robot_,
                                                             runtime->rig_, sim_config);
  SimulationDriverConfig driver;
  driver.max_time_s = c.max_time_s;
  driver.control_period_s = 1.0 / c.control_rate_hz;
  driver.replan_period_s = c.planning.replan_period_s;
  runtime->driver_ = std::make_unique<SimulationDriver>(std::move(simulator), *runtime->mediator_,
                                                        driver, runtime->recording_.get());
  runtime->MakeWorkers(AreaFor(*runtime->world_, c.mapping.resolution_m));
  return runtime;
}

robotio::Expected<std::unique_ptr<MissionRuntime>> MissionRuntime::CreateOnDevices(
    MissionConfig config, DeviceSources sources) {
  if (sources.base == nullptr || !sources.deadman) {
    return robotio::Error{"a mission on the robot needs the base and the dead-man switch"};
  }
  if (config.poses == PoseSource::kGroundTruth) {
    return robotio::Error{"poses: the real robot has no ground truth; use slam or odometry"};
  }
  config.world_file.clear();
  config.speed = 1.0;  // Real time: the clock follows the host's.
  auto prepared = Prepare(std::move(config), std::nullopt, std::nullopt);
  if (!prepared) return prepared.error();
  std::unique_ptr<MissionRuntime> runtime = std::move(*prepared);
  const MissionConfig& c = runtime->config_;
  for (const DeviceCamera& camera : sources.cameras) {
    if (camera.camera == nullptr ||
        camera.camera->sensor_id() >= static_cast<int>(runtime->rig_.kinects.size())) {
      return robotio::Error{camera.name + ": not a Kinect of the rig " + c.rig_file};
    }
  }
  DeviceDriverConfig driver;
  driver.max_time_s = c.max_time_s;
  runtime->driver_ = std::make_unique<DeviceDriver>(std::move(sources), *runtime->mediator_,
                                                    driver, runtime->recording_.get());
  runtime->MakeWorkers(SquareArea(c.area_m, c.mapping.resolution_m));
  return runtime;
}

robotio::Expected<std::unique_ptr<MissionRuntime>> MissionRuntime::CreateFromRecording(
    MissionConfig config, const std::string& recording_dir) {
  auto opened = robotio::RecordingReader::Open(recording_dir);
  if (!opened) return opened.error();
  auto reader = std::make_unique<robotio::RecordingReader>(std::move(*opened));
  if (reader->depth_entries().empty()) return robotio::Error{recording_dir + ": no depth frames"};
  if (config.poses == PoseSource::kGroundTruth && reader->ground_truth().empty()) {
    return robotio::Error{recording_dir + ": no groundtruth.txt for poses from ground truth"};
  }
  if (config.poses != PoseSource::kGroundTruth && reader->odometry().empty()) {
    return robotio::Error{recording_dir +
                          ": no odometry.txt, which a mission's SLAM needs; map it with "
                          "`dynamap map --log` (registration alone) instead"};
  }
  if (!config.rig_file.empty()) {  // A calibrated rig instead of the recorded one.
    auto rig = robotio::LoadRig(config.rig_file);
    if (!rig) return rig.error();
    if (auto used = reader->UseExtrinsics(*rig, config.rig_file); !used) return used.error();
  }
  std::optional<robotio::sim::World> world;
  if (!reader->meta().world.empty()) {
    auto loaded = robotio::sim::LoadWorld(reader->meta().world);
    if (!loaded) return loaded.error();
    world = std::move(*loaded);
  }
  config.record = false;
  RecordingDriverConfig driver;
  driver.control_period_s = 1.0 / config.control_rate_hz;
  driver.replan_period_s = config.planning.replan_period_s;
  driver.max_time_s = config.max_time_s;
  const robotio::Rig rig = reader->rig();
  // Ground truth (doors, people) is judged at the end of what is replayed.
  config.max_time_s =
      std::min(config.max_time_s, robotio::NanosToSeconds(reader->last_stamp_ns()));
  config.world_file = reader->meta().world;
  auto prepared = Prepare(std::move(config), std::move(world), rig);
  if (!prepared) return prepared.error();
  std::unique_ptr<MissionRuntime> runtime = std::move(*prepared);
  runtime->reader_ = std::move(reader);
  runtime->driver_ =
      std::make_unique<RecordingDriver>(*runtime->reader_, *runtime->mediator_, driver);
  const MissionConfig& c = runtime->config_;
  if (runtime->world_) {
    runtime->MakeWorkers(AreaFor(*runtime->world_, c.mapping.resolution_m));
  } else {
    runtime->MakeWorkers(SquareArea(c.area_m, c.mapping.resolution_m));
  }
  return runtime;
}

void MissionRuntime::MakeWorkers(const planning::GridMap& area) {
  const MissionConfig& config = config_;
  if (world_) {  // What will be reachable at the end, for the live explored share.
    live_truth_ = std::make_shared<const TruthGrid>(
        BuildTruthGrid(*world_, area, footprint_radius_m_,
                       config.planning.projection.robot_height_m, config.max_time_s));
  }
  MappingWorkerConfig mapping;
  mapping.poses = config.poses;
  mapping.mapping = config.mapping;
  mapping.slam = config.slam;
  mapping.projection = config.planning.projection;
  mapping.area = area;
  mapping.save_file = config.out_dir + "/map.ot";
  mapping.save_period_s = config.save_period_s;
  mapping.inspection_distance_m = config.planning.coverage.inspection_distance_m;
  mapping_ = std::make_unique<MappingWorker>(*mediator_, rig_, mapping);

  PlanningWorkerConfig planning;
  planning.planning = config.planning;
  planning.known_floor_radius_m = config.known_floor_radius_m;
  // The ring the Kinects cannot see, plus the widest floor gap the planner closes anyway.
  const double blind_m =
      robotio::FloorBlindRadius(rig_) + config.planning.projection.max_floor_gap_m;
  planning.start_floor_radius_m = std::max(config.known_floor_radius_m, blind_m);
  spdlog::debug("floor assumed within {:.2f} m of the start", planning.start_floor_radius_m);
  // Frontier viewpoints beyond the blind ring, so the unseen floor there comes into view;
  // a value set in the planning file wins.
  if (planning.planning.targets.min_view_distance_m <= 0.0) {
    planning.planning.targets.min_view_distance_m = blind_m;
  }
  planning.resolution_m = config.mapping.resolution_m;
  planning_ = std::make_unique<PlanningWorker>(*mediator_, planning);

  ControlWorkerConfig control;
  control.rate_hz = config.control_rate_hz;
  control.follower = config.planning.follower;
  control.guard = config.planning.guard;
  control.cost = config.planning.cost;
  control.memory = config.planning.memory;
  control.path_shift = config.planning.path_shift;
  // The shift makes up for a map pose that is off the map; true poses are not.
  if (config.poses == PoseSource::kGroundTruth) control.path_shift.enabled = false;
  control_ = std::make_unique<ControlWorker>(*mediator_, rig_, control);
}

std::optional<std::string> MissionRuntime::device_error() const {
  return driver_ ? driver_->device_error() : std::nullopt;
}

void MissionRuntime::Start() {
  if (!mediator_->control.Start()) return;
  started_ = std::chrono::steady_clock::now();
  process_cpu_at_start_s_ = ProcessCpuSeconds();
  threads_.emplace_back([this] {
    driver_->Run();
    mediator_->WakeAll();  // Time limit or stop: everyone leaves.
    cpu_.simulation_s = ThreadCpuSeconds();
  });
  threads_.emplace_back([this] {
    mapping_->Run();
    cpu_.mapping_s = ThreadCpuSeconds();
  });
  threads_.emplace_back([this] {
    planning_->Run();
    cpu_.planning_s = ThreadCpuSeconds();
  });
  threads_.emplace_back([this] {
    control_->Run();
    cpu_.control_s = ThreadCpuSeconds();
  });
  threads_.emplace_back([this] { Monitor(); });
}

void MissionRuntime::Monitor() {
  while (!mediator_->control.stopping()) {
    if (mediator_->counters.returned_to_start.load()) {
      spdlog::info("exploration complete: back at the start");
      mediator_->WakeAll();
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

void MissionRuntime::RequestMapCopy() { mediator_->map_copy_wanted = true; }

std::pair<std::shared_ptr<const mapping::DualOcTree>, std::uint64_t>
MissionRuntime::LatestMapCopy() const {
  const auto copy = mediator_->map_copy.Get();
  if (!copy) return {nullptr, 0};
  return {copy->value, copy->version};
}

bool MissionRuntime::Pause() { return mediator_->control.Pause(); }
bool MissionRuntime::Resume() { return mediator_->control.Resume(); }
void MissionRuntime::Stop() { mediator_->WakeAll(); }

void MissionRuntime::Wait() {
  for (std::thread& t : threads_) {
    if (t.joinable()) t.join();
  }
  joined_ = true;
  if (started_ != std::chrono::steady_clock::time_point{}) {
    wall_time_s_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    const double process = ProcessCpuSeconds() - process_cpu_at_start_s_;
    cpu_.other_s = std::max(0.0, process - cpu_.simulation_s - cpu_.mapping_s -
                                     cpu_.planning_s - cpu_.control_s);
  }
  mediator_->control.MarkFinished();
}

bool MissionRuntime::finished() const {
  return mediator_->control.state() == MissionState::kFinished;
}

MissionSnapshot MissionRuntime::Snapshot() const {
  MissionSnapshot s;
  const Mediator& m = *mediator_;
  s.state = m.control.state();
  s.sim_time_s = robotio::NanosToSeconds(m.clock.now_ns());
  s.pose = m.CurrentPose();
  s.trail = m.Trail();
  if (auto grid = m.grid.Get()) {
    s.grid = std::shared_ptr<const planning::GridMap>(grid->value, &grid->value->map);
  }
  if (auto plan = m.plan.Get()) {
    s.target_kind = plan->value.kind;
    s.has_goal = plan->value.has_goal;
    s.goal = plan->value.goal_map;
    s.path = plan->value.path_map;
    s.candidates = plan->value.frontier_targets_map;
    s.unreachable_frontiers = plan->value.unreachable_frontiers_map;
    s.blacklisted_frontiers = plan->value.blacklisted_frontiers_map;
  }
  for (const auto& slot : m.latest_depth) {
    if (auto frame = slot.Get()) s.depth.push_back(frame->value);
  }
  s.distance_m = m.odometry.distance_m();
  s.frames_delivered = m.frames.delivered();
  s.frames_dropped = m.frames.dropped();
  s.frames_processed = m.counters.frames_processed.load();
  s.collisions = m.counters.collisions.load();
  s.loop_closures = m.counters.loop_closures.load();
  s.guard_stops = m.counters.guard_stops.load();
  if (auto command = m.command.Get()) s.command = command->value;
  s.exploration_done = m.counters.exploration_done.load();
  s.time_limit_s = config_.max_time_s;
  s.ate_so_far_m = m.LiveAte();
  if (live_truth_ && s.grid) s.explored_free_fraction = ExploredFreeFraction(*live_truth_, *s.grid);
  return s;
}

robotio::Expected<MissionReport> MissionRuntime::Finish() {
  if (!joined_) Wait();
  const Mediator& m = *mediator_;
  const std::string& out = config_.out_dir;
  MissionReport r;
  r.completed = m.counters.returned_to_start.load();
  r.mission_time_s = robotio::NanosToSeconds(m.clock.now_ns());
  r.wall_time_s = wall_time_s_;
  r.cpu = cpu_;
  r.collisions = m.counters.collisions.load();
  r.frames_delivered = m.frames.delivered();
  r.frames_dropped = m.frames.dropped();
  r.frames_processed = m.counters.frames_processed.load();
  r.registrations_accepted = m.counters.registrations_accepted.load();
  r.registrations_rejected = m.counters.registrations_rejected.load();
  r.guard_stops = m.counters.guard_stops.load();
  r.map_guard_stops = m.counters.map_guard_stops.load();
  r.map_guard_give_ups = m.counters.map_guard_give_ups.load();
  r.stall_stops = m.counters.stall_stops.load();
  r.path_shifted_s = static_cast<double>(m.counters.path_shift_steps.load()) /
                     config_.control_rate_hz;
  r.path_shift_max_m = 1e-3 * static_cast<double>(m.counters.path_shift_max_mm.load());
  r.plans = m.counters.plans.load();
  r.unreachable_targets = m.counters.unreachable_targets.load();
  r.blocked_plans = m.counters.blocked_plans.load();
  r.squeezed_plans = m.counters.squeezed_plans.load();
  r.last_try_regions = m.counters.last_try_regions.load();
  if (const auto plan = m.plan.Get()) {
    r.unreachable_frontiers = plan->value.unreachable_frontiers_map;
    r.blacklisted_frontiers = plan->value.blacklisted_frontiers_map;
  }
  r.plan_median_ms = Percentile(planning_->plan_ms(), 0.5);
  r.plan_p95_ms = Percentile(planning_->plan_ms(), 0.95);
  r.insert_median_ms = mapping_->median_insert_ms();
  r.insert_p95_ms = mapping_->p95_insert_ms();

  mapping_->CloseLoops();
  if (const mapping::LoopClosureSummary* closure = mapping_->loop_closure()) {
    r.loop_closures =
        static_cast<std::int64_t>(closure->Count(mapping::LoopClosureOutcome::kClosed));
  }
  const robotio::Trajectory truth = m.GroundTruth();
  const robotio::Trajectory online = m.Estimates();
  const robotio::Trajectory estimate = mapping_->Corrected(online);
  // On the robot nothing is known to score against: those figures stay empty (null).
  constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();
  const robotio::Trajectory& driven = world_ ? truth : estimate;
  for (std::size_t i = 1; i < driven.size(); ++i) {
    r.path_length_m += (driven[i].pose.translation() - driven[i - 1].pose.translation()).norm();
  }
  r.ate_rmse_m = r.online_ate_rmse_m = r.odometry_ate_rmse_m = kUnknown;
  mapping::TrajectoryEvaluationConfig ate;
  ate.max_stamp_difference_s = 0.011;  // Ground truth comes at the gyro's 100 Hz.
  if (auto e = mapping::EvaluateTrajectory(truth, estimate, ate)) r.ate_rmse_m = e->ate_m.rmse;
  if (auto e = mapping::EvaluateTrajectory(truth, online, ate)) r.online_ate_rmse_m = e->ate_m.rmse;
  if (auto e = mapping::EvaluateTrajectory(truth, m.OdometryEstimates(), ate)) {
    r.odometry_ate_rmse_m = e->ate_m.rmse;
  }
  std::optional<SurfaceCoverageResult> coverage;  // Only against the simulator's truth.
  std::optional<mapping::PointAccuracy> accuracy;
  if (world_) {
    accuracy = mapping_->Accuracy();
    r.static_accuracy = accuracy->static_accuracy;
    r.dynamic_accuracy = accuracy->dynamic_accuracy;
    r.associated_accuracy = accuracy->associated_accuracy;
    r.dynamic_accuracy_above_floor = accuracy->dynamic_accuracy_above_floor;
    r.static_accuracy_above_floor = accuracy->static_accuracy_above_floor;
    const TruthGrid truth_grid =
        BuildTruthGrid(*world_, mapping_->grid(), footprint_radius_m_,
                       config_.planning.projection.robot_height_m, r.mission_time_s);
    r.explored_free_fraction = ExploredFreeFraction(truth_grid, mapping_->grid());
    const robotio::PointList samples =
        robotio::sim::SampleStaticSurfaces(*world_, config_.mapping.resolution_m);
    coverage = SurfaceCoverage(
        truth_grid, samples, config_.planning.projection.robot_height_m,
        config_.planning.coverage.inspection_distance_m,
        [this](const Eigen::Vector3f& p) { return mapping_->Inspected(p); });
    r.surface_coverage = coverage->Fraction();
  } else {
    r.static_accuracy = r.dynamic_accuracy = r.associated_accuracy = kUnknown;
    r.dynamic_accuracy_above_floor = r.static_accuracy_above_floor = kUnknown;
    r.explored_free_fraction = r.surface_coverage = kUnknown;
  }

  const auto write = [&](const std::string& name, robotio::Status status) -> robotio::Status {
    if (!status) return status;
    r.files.push_back(name);
    return robotio::Ok{};
  };
  const mapping::DualOcTree& tree = mapping_->map().tree();
  std::vector<robotio::Status> results = {
      write("map.ot", mapping::SaveDualMap(tree, out + "/map.ot")),
      write("static.bt", mapping::ExportBinary(tree, mapping::MapChannel::kStatic, out + "/static.bt")),
      write("dynamic.bt",
            mapping::ExportBinary(tree, mapping::MapChannel::kDynamic, out + "/dynamic.bt")),
      // A mission stopped before its first scan has no map to picture (and still a report).
      tree.getRoot() == nullptr
          ? robotio::Status(robotio::Ok{})
          : write("map3d_topdown.png", mapping::WriteTopDownPng(tree, out + "/map3d_topdown.png")),
      write("trajectory.tum", robotio::WriteTumTrajectory(estimate, out + "/trajectory.tum")),
      mapping_->loop_closure() == nullptr
          ? robotio::Status(robotio::Ok{})
          : write("trajectory_online.tum",
                  robotio::WriteTumTrajectory(online, out + "/trajectory_online.tum")),
      mapping_->loop_closure() == nullptr
          ? robotio::Status(robotio::Ok{})
          : write("loop_closures.csv",
                  robotio::WriteFileAtomically(
                      out + "/loop_closures.csv",
                      mapping::LoopClosureAttemptsCsv(mapping_->loop_closure()->attempts))),
      world_ ? write("groundtruth.tum", robotio::WriteTumTrajectory(truth, out + "/groundtruth.tum"))
             : robotio::Status(robotio::Ok{}),
      write("map2d.png", WriteMapPicture(mapping_->grid(), ToPoses(estimate), ToPoses(truth),
                                         {Snapshot().candidates, r.unreachable_frontiers,
                                          r.blacklisted_frontiers},
                                         out + "/map2d.png")),
      write("map2d.pgm", WriteRosMap(mapping_->grid(), out + "/map2d.pgm", out + "/map2d.yaml")),
  };
  if (r.files.back() == "map2d.pgm") r.files.push_back("map2d.yaml");
  if (coverage) {
    results.push_back(write("coverage.png", WriteCoveragePicture(mapping_->grid(), *coverage,
                                                                 out + "/coverage.png")));
  }
  if (accuracy) {
    const mapping::MisclassifiedVoxels misclassified = mapping_->Misclassified();
    results.push_back(write("accuracy.png", WriteAccuracyPicture(mapping_->grid(), misclassified,
                                                                 *accuracy, out + "/accuracy.png")));
    results.push_back(write("accuracy_errors.csv",
                            robotio::WriteFileAtomically(
                                out + "/accuracy_errors.csv",
                                mapping::MisclassifiedVoxelsCsv(misclassified))));
  }
  if (recording_) r.files.push_back("recording");
  for (const auto& status : results) {
    if (!status) return status.error();
  }
  r.files.push_back("report.json");
  nlohmann::json extra = {{"source", world_ ? "simulator" : "hardware"},
                          {"poses", ToString(config_.poses)},
                          {"speed", config_.speed},
                          {"kinect_width", config_.kinect_width},
                          {"kinect_height", config_.kinect_height},
                          {"targets", config_.planning.targets.strategy}};
  if (const mapping::LoopClosureSummary* closure = mapping_->loop_closure()) {
    using Outcome = mapping::LoopClosureOutcome;
    extra["loop_closure"] = {{"keyframes", closure->keyframes},
                             {"candidates", closure->attempts.size()},
                             {"poor_fits", closure->Count(Outcome::kPoorFit)},
                             {"implausible", closure->Count(Outcome::kImplausible)},
                             {"closures", closure->Count(Outcome::kClosed) +
                                              closure->Count(Outcome::kDropped)},
                             {"closures_dropped", closure->Count(Outcome::kDropped)},
                             {"largest_correction_m", closure->largest_correction_m}};
  }
  if (world_) {
    extra["world"] = config_.world_file;
    extra["seed"] = config_.seed;
  } else {
    extra["collisions"] = nullptr;  // The robot has no contact sensing.
    extra["device_error"] =
        device_error() ? nlohmann::json(*device_error()) : nlohmann::json(nullptr);
  }
  if (auto status = WriteReportJson(r, extra.dump(), out + "/report.json"); !status) {
    return status.error();
  }
  return r;
}

}  // namespace dynamap::app::runtime
