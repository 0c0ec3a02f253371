#include "cli/MapCommand.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/CommandSupport.hpp"
#include "cli/ProgressLine.hpp"
#include "cli/RecordingScans.hpp"
#include "cli/SlamRun.hpp"
#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/mapping/MapEvaluation.hpp"
#include "dynamap/mapping/MapExport.hpp"
#include "dynamap/mapping/MapFiles.hpp"
#include "dynamap/mapping/MappingConfig.hpp"
#include "dynamap/mapping/PointCloudFiles.hpp"
#include "dynamap/mapping/TrajectoryEvaluation.hpp"
#include "dynamap/mapping/TrajectoryPlot.hpp"
#include "dynamap/robotio/AtomicFile.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/hardware/OniUnpacking.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"
#include "dynamap/robotio/sim/StaticSurfaces.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app {
namespace {

constexpr const char* kCommand = "map";
namespace fs = std::filesystem;

struct MapOptions {
  std::string log;
  std::string out;
  std::string poses = "slam";
  std::string trajectory;  // TUM file of T_map_base poses to map with; "" = --poses.
  std::string reference;  // SLAM registration target (--poses slam); "" = the settings'.
  std::string slam;       // SLAM settings file (keys of mapping::SlamConfig); "" = defaults.
  std::string slam_odometry = "wheels";  // Or "groundtruth" (diagnosis, see SlamRunOptions).
  std::string mode = "playback";       // Run mode of the SLAM pass (--poses slam).
  std::string mapping_file;  // Map settings file (keys of mapping::MappingConfig); "" = defaults.
  // The map settings' defaults; given on the command line they win over --mapping.
  std::string update = mapping::UpdateModeName(mapping::MappingConfig{}.update);
  double resolution_m = mapping::MappingConfig{}.resolution_m;
  double max_range_m = mapping::MappingConfig{}.max_range_m;
  bool update_given = false, resolution_given = false, max_range_given = false;  // On the command line.
  int eval_stride = 2;
  std::string robot = "robots/segway_rmp50.yaml";
  std::string rig;  // Kinect poses and latencies to map with instead of the recorded ones.
};

using Clock = std::chrono::steady_clock;
double Seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

void Check(const robotio::Status& status) {
  if (!status) FailCommand(kCommand, status.error().message);
}

robotio::Trajectory SelectPoses(const robotio::RecordingReader& reader, const MapOptions& o) {
  if (!o.trajectory.empty()) {
    auto trajectory = robotio::ReadTumTrajectory(o.trajectory);
    if (!trajectory) FailCommand(kCommand, trajectory.error().message);
    if (trajectory->empty()) {
      FailCommand(kCommand, o.trajectory +
                                ": no poses (expected lines 'timestamp tx ty tz qx qy qz qw')");
    }
    return *trajectory;
  }
  if (o.poses == "groundtruth") {
    if (reader.ground_truth().empty()) {
      FailCommand(kCommand, reader.dir() + ": no groundtruth.txt; use --poses odometry");
    }
    return reader.ground_truth();
  }
  if (reader.odometry().empty()) FailCommand(kCommand, reader.dir() + ": no odometry.txt");
  const std::string robot_file = fs::exists(o.robot) ? o.robot : ResourcePath(o.robot);
  auto robot = robotio::sim::LoadRobotConfig(robot_file);
  if (!robot) FailCommand(kCommand, robot.error().message);
  return IntegrateWheelOdometry(reader.odometry(), robot->track_width_m);
}

SlamRunResult RunSlamPass(const robotio::RecordingReader& reader, const MapOptions& o,
                          const mapping::MappingConfig& config) {
  SlamRunOptions options;
  options.mapping = config;
  if (!o.slam.empty()) {
    auto slam = mapping::LoadSlamConfig(o.slam);
    if (!slam) FailCommand(kCommand, slam.error().message);
    options.slam = *slam;
  }
  if (!o.reference.empty()) {
    options.slam.reference = o.reference == "previous" ? mapping::ReferenceStrategy::kPrevious
                             : o.reference == "map"    ? mapping::ReferenceStrategy::kMap
                                                       : mapping::ReferenceStrategy::kCombined;
  }
  options.mode = o.mode == "simulate" ? RunMode::kSimulate : RunMode::kPlayback;
  options.odometry_from_ground_truth = o.slam_odometry == "groundtruth";
  const std::string robot_file = fs::exists(o.robot) ? o.robot : ResourcePath(o.robot);
  auto robot = robotio::sim::LoadRobotConfig(robot_file);
  if (!robot) FailCommand(kCommand, robot.error().message);
  options.motion.track_width_m = robot->track_width_m;
  ProgressLine progress("slam");
  auto result = RunSlam(reader, options, [&](double f) { progress.Update(f, "scans"); });
  if (!result) FailCommand(kCommand, result.error().message);
  progress.Finish(std::to_string(result->frames_processed) + " frames");
  if (result->loop_closure) {
    const mapping::LoopClosureSummary& closure = *result->loop_closure;
    std::fprintf(stderr, "loop closure: %zu keyframes, %zu of %zu revisits closed, largest correction "
                "%.3f m (%.1f s)\n",
                closure.keyframes, closure.Count(mapping::LoopClosureOutcome::kClosed),
                closure.attempts.size(),
                closure.largest_correction_m, result->loop_closure_s);
  }
  return std::move(*result);
}

nlohmann::json MedianAndP95(std::vector<double> seconds) {
  if (seconds.empty()) return {{"median_s", nullptr}, {"p95_s", nullptr}};
  std::sort(seconds.begin(), seconds.end());
  const auto at = [&](double q) {
    return seconds[static_cast<std::size_t>(q * static_cast<double>(seconds.size() - 1) + 0.5)];
  };
  return {{"median_s", at(0.5)}, {"p95_s", at(0.95)}};
}

void AddSlamReport(const robotio::RecordingReader& reader, const MapOptions& o,
                   const SlamRunResult& slam, nlohmann::json* report) {
  if (slam.tracking_only) {
    (*report)["reference"] = "keyframes";
  } else {
    (*report)["reference"] = mapping::ReferenceStrategyName(slam.reference);
    if (!o.slam.empty()) (*report)["slam_settings"] = o.slam;
    (*report)["slam_odometry"] = o.slam_odometry;
  }
  (*report)["mode"] = o.mode;
  (*report)["pose_source"] = slam.tracking_only ? "registration only (no odometry)"
                                                 : "odometry, gyro and registration";
  (*report)["ate_aligned"] = slam.tracking_only;
  if (slam.tracking_only) {
    (*report)["keyframes"] = slam.keyframes;
    (*report)["track_restarts"] = slam.track_restarts;
  }
  (*report)["frames_processed"] = slam.frames_processed;
  (*report)["frames_dropped"] = slam.frames_dropped;
  (*report)["registrations_accepted"] = slam.registrations_accepted;
  (*report)["registrations_rejected"] = slam.registrations_rejected;
  (*report)["slam_stage_times"] = {{"preprocess", MedianAndP95(slam.preprocess_s)},
                                   {"register", MedianAndP95(slam.register_s)},
                                   {"map_update", MedianAndP95(slam.update_s)},
                                   {"total", MedianAndP95(slam.total_s)}};
  double busy_s = 0.0;
  for (double s : slam.total_s) busy_s += s;
  (*report)["slam_frames_per_s"] =
      busy_s > 0.0 ? static_cast<double>(slam.frames_processed) / busy_s : 0.0;
  // DESIGN.md, Evaluation: no alignment; ground truth and estimate share the map origin.
  // Tracked without odometry (a TUM sequence), the estimate's frame is the first camera
  // pose and the ground truth's the motion capture's: then aligned rigidly, as the TUM
  // benchmark does.
  const auto& truth = reader.ground_truth();
  mapping::TrajectoryEvaluationConfig evaluation;
  evaluation.align = slam.tracking_only;
  const auto estimate = mapping::EvaluateTrajectory(truth, slam.trajectory, evaluation);
  const auto odometry = mapping::EvaluateTrajectory(truth, slam.odometry, {});
  (*report)["ate_rmse_m"] = estimate ? nlohmann::json(estimate->ate_m.rmse) : nlohmann::json();
  (*report)["odometry_ate_rmse_m"] =
      odometry ? nlohmann::json(odometry->ate_m.rmse) : nlohmann::json();
  if (slam.loop_closure) {
    const auto before =
        mapping::EvaluateTrajectory(truth, slam.trajectory_before_loop_closure, evaluation);
    (*report)["ate_rmse_m_before_loop_closure"] =
        before ? nlohmann::json(before->ate_m.rmse) : nlohmann::json();
    const mapping::LoopClosureSummary& closure = *slam.loop_closure;
    using Outcome = mapping::LoopClosureOutcome;
    (*report)["loop_closure"] = {{"keyframes", closure.keyframes},
                                 {"candidates", closure.attempts.size()},
                                 {"poor_fits", closure.Count(Outcome::kPoorFit)},
                                 {"implausible", closure.Count(Outcome::kImplausible)},
                                 {"closures", closure.Count(Outcome::kClosed) + closure.Count(Outcome::kDropped)},
                                 {"graph_converged", closure.graph.converged},
                                 {"closures_dropped", closure.Count(Outcome::kDropped)},
                                 {"largest_correction_m", closure.largest_correction_m},
                                 {"seconds", slam.loop_closure_s}};
  }
  const bool rpe = estimate && estimate->rpe;
  (*report)["rpe_trans_m_per_m"] = rpe ? nlohmann::json(estimate->rpe->trans_m_per_m) : nlohmann::json();
  (*report)["rpe_rot_deg_per_m"] = rpe ? nlohmann::json(estimate->rpe->rot_deg_per_m) : nlohmann::json();
}

// The recording's world, for the true static surfaces; nullopt when it has none.
std::optional<robotio::PointList> SurfaceSamples(const robotio::RecordingReader& reader,
                                                 double spacing_m) {
  if (reader.meta().world.empty()) return std::nullopt;
  auto world = robotio::sim::LoadWorld(reader.meta().world);
  if (!world) {
    FailCommand(kCommand, reader.dir() + ": the world it was recorded in (its meta.yaml "
                          "`world`, needed to score the map) cannot be loaded: " +
                              world.error().message);
  }
  if (reader.meta().duration_s > 0.0) world->duration_s = reader.meta().duration_s;
  return robotio::sim::SampleStaticSurfaces(*world, spacing_m);
}

bool IsOniFile(const std::string& path) {
  return path.size() > 4 && path.compare(path.size() - 4, 4, ".oni") == 0;
}

// An OpenNI2 recording is first unpacked into OUT/recording (dynamap's format, one level
// camera, no odometry) and mapped from there.
std::string UnpackedRecording(const MapOptions& o) {
  const std::string dir = (fs::path(o.out) / "recording").string();
  std::error_code ec;
  if (fs::exists(dir, ec)) {
    FailCommand(kCommand, dir + ": already exists; give --out a new folder for " + o.log);
  }
  ProgressLine progress("unpacking");
  auto unpacked = robotio::hardware::UnpackOniFile(
      o.log, dir, [&](double f) { progress.Update(f, "frames"); });
  if (!unpacked) FailCommand(kCommand, unpacked.error().message);
  progress.Finish(std::to_string(unpacked->frames) + " frames");
  return dir;
}

nlohmann::json RunMap(const MapOptions& o) {
  const auto start = Clock::now();
  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) FailCommand(kCommand, o.out + ": cannot create the output directory: " + ec.message());
  auto opened = robotio::RecordingReader::Open(IsOniFile(o.log) ? UnpackedRecording(o) : o.log);
  if (!opened) FailCommand(kCommand, opened.error().message);
  if (!o.rig.empty()) {
    auto rig = robotio::LoadRig(o.rig);
    if (!rig) FailCommand(kCommand, rig.error().message);
    Check(opened->UseExtrinsics(*rig, o.rig));
  }
  const robotio::RecordingReader& reader = *opened;
  mapping::MappingConfig config;
  if (!o.mapping_file.empty()) {
    auto loaded = mapping::LoadMappingConfig(o.mapping_file);
    if (!loaded) FailCommand(kCommand, loaded.error().message);
    config = *loaded;
  }
  if (o.resolution_given) config.resolution_m = o.resolution_m;
  if (o.max_range_given) config.max_range_m = o.max_range_m;
  if (o.update_given) {
    config.update = o.update == "regular" ? mapping::UpdateMode::kRegular
                                          : mapping::UpdateMode::kDynamic;
  }
  Check(mapping::ValidateMappingConfig(config, "command line"));
  // Loaded first: a world that cannot be loaded stops the command before the mapping.
  const std::optional<robotio::PointList> surface_samples =
      SurfaceSamples(reader, config.resolution_m / 2.0);
  // With --poses slam a SLAM pass over the recording estimates the pose of every frame
  // (its own dual map steers the dynamic-point filter); the map below is then built from
  // those poses like from any other pose source.
  std::optional<SlamRunResult> slam;
  if (o.poses == "slam" && o.trajectory.empty()) slam = RunSlamPass(reader, o, config);
  const robotio::Trajectory poses = slam ? slam->frame_poses : SelectPoses(reader, o);
  mapping::DualMap map(config);
  const bool labelled = !reader.label_entries().empty();
  mapping::PointAccuracyCounter accuracy(config.resolution_m, config.max_range_m, o.eval_stride);

  double load_s = 0.0, project_s = 0.0, insert_s = 0.0, label_s = 0.0;
  std::size_t frames = 0, skipped = 0;
  const auto& entries = reader.depth_entries();
  // Both Kinects of one instant are inserted as one scan: a voxel both see is updated
  // once, so evidence accumulates at the same pace wherever it is seen from.
  const RecordingScans grouped = GroupRecordingIntoScans(reader, reader.rig());
  skipped = entries.size() - grouped.order.size();
  ProgressLine progress("mapping");
  std::size_t done = 0;
  for (const std::vector<std::size_t>& scan : grouped.scans) {
    std::vector<robotio::DepthFrame> scan_frames;
    std::vector<robotio::KinectMount> mounts;
    std::vector<Eigen::Isometry3d> scan_poses;
    std::vector<robotio::DepthRays> rays;
    for (std::size_t k : scan) {
      auto t = Clock::now();
      auto frame = reader.LoadDepth(entries[grouped.order[k]]);
      if (!frame) FailCommand(kCommand, frame.error().message);
      load_s += Seconds(t);
      robotio::KinectMount mount = reader.rig().kinects[static_cast<std::size_t>(frame->sensor_id)];
      mount.max_range_m = std::min(mount.max_range_m, config.max_range_m);
      const Eigen::Isometry3d T_map_base = PoseAtStamp(poses, frame->stamp_ns);
      t = Clock::now();
      rays.push_back(map.RaysOf(*frame, mount, T_map_base));
      project_s += Seconds(t);
      scan_frames.push_back(std::move(*frame));
      mounts.push_back(mount);
      scan_poses.push_back(T_map_base);
    }
    auto t = Clock::now();
    map.InsertScan(rays);
    insert_s += Seconds(t);
    frames += scan.size();
    if (labelled) {
      t = Clock::now();
      for (std::size_t j = 0; j < scan.size(); ++j) {
        if (auto labels = reader.LoadLabels(entries[grouped.order[scan[j]]])) {
          accuracy.Add(scan_frames[j], *labels, mounts[j], scan_poses[j]);
        }
      }
      label_s += Seconds(t);
    }
    done += scan.size();
    progress.Update(static_cast<double>(done) / static_cast<double>(grouped.order.size()),
                    std::to_string(done) + "/" + std::to_string(grouped.order.size()) + " frames");
  }
  progress.Finish(std::to_string(frames) + " frames");

  auto t = Clock::now();
  const fs::path out(o.out);
  Check(mapping::SaveDualMap(map.tree(), (out / "map.ot").string()));
  Check(mapping::ExportBinary(map.tree(), mapping::MapChannel::kStatic, (out / "static.bt").string()));
  Check(mapping::ExportBinary(map.tree(), mapping::MapChannel::kDynamic, (out / "dynamic.bt").string()));
  const robotio::PointList static_points = mapping::OccupiedVoxelCentres(map.tree(), mapping::MapChannel::kStatic);
  const robotio::PointList dynamic_points = mapping::OccupiedVoxelCentres(map.tree(), mapping::MapChannel::kDynamic);
  Check(mapping::WritePly(static_points, (out / "static.ply").string()));
  Check(mapping::WritePcd(static_points, (out / "static.pcd").string()));
  Check(mapping::WritePly(dynamic_points, (out / "dynamic.ply").string()));
  Check(mapping::WritePcd(dynamic_points, (out / "dynamic.pcd").string()));
  if (map.tree().getRoot() != nullptr) Check(mapping::WriteTopDownPng(map.tree(), (out / "topdown.png").string()));
  const double write_s = Seconds(t);

  nlohmann::json report = {
      {"command", "map"},
      {"log", reader.dir()},
      {"poses", o.trajectory.empty() ? o.poses : "trajectory"},
      {"rig", o.rig.empty() ? "recorded" : o.rig},
      {"update", mapping::UpdateModeName(config.update)},
      {"mapping_settings", o.mapping_file.empty() ? "defaults" : o.mapping_file},
      {"persistence_observations", config.persistence_observations},
      {"resolution_m", config.resolution_m},
      {"max_range_m", config.max_range_m},
      {"frames", frames},
      {"frames_skipped", skipped},
      {"map_nodes", map.tree().size()},
      {"static_occupied_voxels", static_points.size()},
      {"dynamic_occupied_voxels", dynamic_points.size()},
  };
  if (!o.trajectory.empty()) {
    report["trajectory"] = o.trajectory;
    // How far the given poses are from the truth (no alignment, as for SLAM's).
    const auto error = mapping::EvaluateTrajectory(reader.ground_truth(), poses, {});
    report["ate_rmse_m"] = error ? nlohmann::json(error->ate_m.rmse) : nlohmann::json();
  }
  if (slam) {
    Check(robotio::WriteTumTrajectory(slam->trajectory, (out / "trajectory.tum").string()));
    Check(robotio::WriteFileAtomically((out / "slam_scans.csv").string(),
                                       ScanRecordsCsv(slam->scans)));
    if (slam->loop_closure) {
      Check(robotio::WriteFileAtomically((out / "loop_closures.csv").string(),
                                         mapping::LoopClosureAttemptsCsv(slam->loop_closure->attempts)));
      // What the SLAM pass gave, for loop closure alone again (bench_loop_closure).
      Check(robotio::WriteTumTrajectory(slam->trajectory_before_loop_closure,
                                        (out / "trajectory_before_loop_closure.tum").string()));
    }
    AddSlamReport(reader, o, *slam, &report);
    // Where along the way the estimate was off, beside what loop closure and odometry
    // alone made of it (not for a tracked camera: its ATE is aligned, the plot is not).
    if (!reader.ground_truth().empty() && !slam->tracking_only) {
      std::vector<mapping::PlottedTrajectory> lines{{"SLAM", slam->trajectory}};
      if (slam->loop_closure) {
        lines.push_back({"before loop closure", slam->trajectory_before_loop_closure});
      }
      lines.push_back({"odometry alone", slam->odometry});
      const std::string plot = (out / "trajectory_error.png").string();
      Check(mapping::WriteTrajectoryErrorPlot(plot, reader.ground_truth(), lines));
      report["trajectory_error_plot"] = plot;
    }
  }
  t = Clock::now();
  if (labelled) {
    const mapping::PointAccuracy a = accuracy.Evaluate(map.tree());
    report["static_accuracy"] = a.static_accuracy;
    report["dynamic_accuracy"] = a.dynamic_accuracy;
    report["associated_accuracy"] = a.associated_accuracy;
    report["static_points"] = a.static_points;
    report["dynamic_points"] = a.dynamic_points;
    report["dynamic_points_near_floor"] = a.dynamic_points_near_floor;
    report["dynamic_kept_near_floor"] = a.dynamic_kept_near_floor;
    report["dynamic_accuracy_above_floor"] = a.dynamic_accuracy_above_floor;
    report["static_points_near_floor"] = a.static_points_near_floor;
    report["static_kept_near_floor"] = a.static_kept_near_floor;
    report["static_accuracy_above_floor"] = a.static_accuracy_above_floor;
    report["evaluation_pixel_stride"] = o.eval_stride;
    Check(robotio::WriteFileAtomically(
        (out / "accuracy_errors.csv").string(),
        mapping::MisclassifiedVoxelsCsv(accuracy.Misclassified(map.tree()))));
  }
  if (surface_samples) {
    const mapping::SurfaceAccuracy s =
        mapping::EvaluateStaticSurfaces(map.tree(), *surface_samples);
    report["static_map_precision"] = s.static_map_precision;
    report["static_map_completeness"] = s.static_map_completeness;
  }
  const double evaluate_s = Seconds(t) + label_s;
  report["timings_s"] = {{"load", load_s},         {"project", project_s},
                         {"insert", insert_s},     {"evaluate", evaluate_s},
                         {"write", write_s},       {"total", Seconds(start)}};
  report["insert_scans_per_s"] = insert_s > 0.0 ? static_cast<double>(frames) / insert_s : 0.0;
  WriteJsonReport(kCommand, report, (out / "report.json").string());
  return report;
}

}  // namespace

nlohmann::json MapAlongTrajectory(const TrajectoryMapRequest& request) {
  MapOptions o;
  o.log = request.recording_dir;
  o.trajectory = request.trajectory_file;
  o.out = request.out_dir;
  o.mapping_file = request.mapping_file;
  o.rig = request.rig_file;
  return RunMap(o);
}

robotio::Trajectory IntegrateWheelOdometry(const std::vector<robotio::OdometryReading>& odometry,
                                           double track_width_m) {
  robotio::Trajectory trajectory;
  if (odometry.empty()) return trajectory;
  robotio::Pose2D pose;
  trajectory.push_back(robotio::ToStampedPose(odometry.front().stamp_ns, pose));
  for (std::size_t i = 1; i < odometry.size(); ++i) {
    const double left = odometry[i].left_m - odometry[i - 1].left_m;
    const double right = odometry[i].right_m - odometry[i - 1].right_m;
    const double distance = 0.5 * (left + right);
    const double turn = (right - left) / track_width_m;
    pose.x += distance * std::cos(pose.theta + 0.5 * turn);
    pose.y += distance * std::sin(pose.theta + 0.5 * turn);
    pose.theta = robotio::WrapAngle(pose.theta + turn);
    trajectory.push_back(robotio::ToStampedPose(odometry[i].stamp_ns, pose));
  }
  return trajectory;
}

Eigen::Isometry3d PoseAtStamp(const robotio::Trajectory& trajectory, std::int64_t stamp_ns) {
  const auto after = std::lower_bound(
      trajectory.begin(), trajectory.end(), stamp_ns,
      [](const robotio::StampedPose& p, std::int64_t stamp) { return p.stamp_ns < stamp; });
  if (after == trajectory.begin()) return after->pose;
  if (after == trajectory.end()) return trajectory.back().pose;
  const auto before = after - 1;
  const double span = static_cast<double>(after->stamp_ns - before->stamp_ns);
  const double s = span > 0.0 ? static_cast<double>(stamp_ns - before->stamp_ns) / span : 0.0;
  return robotio::Interpolate(robotio::Pose2D::FromIsometry(before->pose),
                              robotio::Pose2D::FromIsometry(after->pose), s)
      .ToIsometry();
}

void RegisterMapCommand(CLI::App& app) {
  auto options = std::make_shared<MapOptions>();
  CLI::App* map = app.add_subcommand(
      "map", "Integrate a recording into the dual static/dynamic 3D map with SLAM (or known) poses; "
             "writes map.ot, static/dynamic .bt/.ply/.pcd, topdown.png, trajectory.tum (and "
             "trajectory_before_loop_closure.tum), slam_scans.csv, "
             "loop_closures.csv, trajectory_error.png (with ground truth), accuracy_errors.csv "
             "(with labels) and report.json");
  map->add_option("--log", options->log,
                  "Recording directory (dynamap's or a TUM RGB-D sequence), or an OpenNI2 .oni "
                  "file; without odometry the camera is tracked by registration alone")
      ->required();
  map->add_option("--out", options->out, "Output directory")->required();
  CLI::Option* poses = map->add_option("--poses", options->poses,
                  "Pose source: slam (odometry + gyro corrected by ICP), groundtruth, odometry")
      ->check(CLI::IsMember({"slam", "groundtruth", "odometry"}))
      ->capture_default_str();
  map->add_option("--trajectory", options->trajectory,
                  "Poses from a TUM trajectory file (T_map_base, e.g. a mission's loop-closed "
                  "trajectory.tum or another SLAM system's) instead of --poses")
      ->check(CLI::ExistingFile)
      ->excludes(poses);
  map->add_option("--reference", options->reference,
                  "SLAM registration target: previous scan, map, or combined (map first; the "
                  "default unless --slam sets another)")
      ->check(CLI::IsMember({"previous", "map", "combined"}));
  map->add_option("--slam-odometry", options->slam_odometry,
                  "What SLAM takes as odometry: wheels (+ gyro) or groundtruth (to measure "
                  "the registration's own drift)")
      ->check(CLI::IsMember({"wheels", "groundtruth"}))
      ->capture_default_str();
  map->add_option("--slam", options->slam,
                  "SLAM settings (YAML with the keys of mapping::SlamConfig, e.g. "
                  "'max_correction_per_rad: 0.05') over the defaults; --reference wins")
      ->check(CLI::ExistingFile);
  map->add_option("--mode", options->mode,
                  "SLAM run mode: playback (every frame, as fast as possible) or simulate "
                  "(recorded pace, late frames dropped and counted)")
      ->check(CLI::IsMember({"playback", "simulate"}))
      ->capture_default_str();
  map->add_option("--mapping", options->mapping_file,
                  "Map settings (YAML under 'mapping:' with the keys of mapping::MappingConfig, "
                  "e.g. 'persistence_observations: 0') over the defaults; --update, "
                  "--resolution and --max-range win when given")
      ->check(CLI::ExistingFile);
  CLI::Option* update = map->add_option("--update", options->update,
                  "dynamic: Tables 4.1/4.2; regular: standard occupancy update")
      ->check(CLI::IsMember({"dynamic", "regular"}))
      ->capture_default_str();
  CLI::Option* resolution = map->add_option("--resolution", options->resolution_m, "Voxel edge (m)")
      ->check(CLI::Range(0.005, 2.0))
      ->capture_default_str();
  CLI::Option* max_range =
      map->add_option("--max-range", options->max_range_m,
                      "Insertion range: depth along the Kinect's optical axis (m)")
      ->check(CLI::Range(0.1, 100.0))
      ->capture_default_str();
  map->add_option("--eval-stride", options->eval_stride,
                  "Every n-th pixel (u and v) counted for static/dynamic accuracy")
      ->check(CLI::Range(1, 64))
      ->capture_default_str();
  map->add_option("--robot", options->robot, "Robot file for the track width (--poses odometry)")
      ->capture_default_str();
  map->add_option("--rig", options->rig,
                  "Rig file whose Kinect poses and latencies replace the recorded ones (e.g. a "
                  "new calibration); intrinsics stay the recording's")
      ->check(CLI::ExistingFile);
  map->callback([options, update, resolution, max_range] {
    options->update_given = update->count() > 0;
    options->resolution_given = resolution->count() > 0;
    options->max_range_given = max_range->count() > 0;
    std::printf("%s\n", RunMap(*options).dump(2).c_str());
  });
}

}  // namespace dynamap::app
