// Loop closure alone on a recorded SLAM pass: the recording's scans placed at the poses
// SLAM gave them (trajectory_before_loop_closure.tum of `dynamap map`, or
// trajectory_online.tum of a recorded mission) are offered as keyframes to one
// LoopClosing per settings file, each closes, and the corrected trajectory is compared
// with the recorded ground truth. Prints per settings file: keyframes, revisits tried and
// closed, closures more than 5 cm off the true relative pose, ATE before and after, and
// the time of Close(). Minutes instead of a SLAM pass per setting when tuning the back end.
//
// The keyframe scans are built as SlamLoop builds its registered scan (both Kinects merged
// at the scan's time, voxel grid in the map frame, then the registration's coarser grid),
// except that points in the dynamic map are not removed: there is no map here. The
// figures are therefore near the pipeline's, not equal (docs/RESULTS.md, SLAM).
//
// Usage: bench_loop_closure --log REC --trajectory TUM [--settings YAML]... [--out DIR]
//   YAML: the keys of mapping::SlamConfig (only loop_closure: matters), as for
//   `dynamap map --slam`; without --settings the defaults. --out writes, per settings
//   file N (0, 1, ...), trajectory_N.tum and loop_closures_N.csv.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli/RecordingScans.hpp"
#include "dynamap/mapping/LoopClosure.hpp"
#include "dynamap/mapping/MappingConfig.hpp"
#include "dynamap/mapping/MotionModel.hpp"
#include "dynamap/mapping/Preprocessing.hpp"
#include "dynamap/mapping/SlamLoop.hpp"
#include "dynamap/mapping/TrajectoryEvaluation.hpp"
#include "dynamap/robotio/AtomicFile.hpp"
#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace {

using namespace dynamap;

[[noreturn]] void Fail(const std::string& message) {
  std::fprintf(stderr, "bench_loop_closure: %s\n", message.c_str());
  std::exit(1);
}

mapping::Trajectory2D Planar(const robotio::Trajectory& trajectory) {
  mapping::Trajectory2D planar;
  for (const robotio::StampedPose& p : trajectory) {
    planar.push_back({p.stamp_ns, robotio::Pose2D::FromIsometry(p.pose)});
  }
  return planar;
}

// The scan SlamLoop registers (base frame at the scan's time), without the dynamic filter.
robotio::PointList RegisteredScan(const std::vector<robotio::DepthFrame>& frames,
                                  const mapping::Trajectory2D& poses, const robotio::Rig& rig,
                                  const mapping::SlamConfig& slam,
                                  const mapping::MappingConfig& mapping) {
  const robotio::Pose2D at_scan = mapping::PoseAt(poses, frames.front().stamp_ns);
  std::vector<robotio::Pose2D> offsets;  // Base at the scan's time ← base at frame k.
  for (const robotio::DepthFrame& frame : frames) {
    offsets.push_back(at_scan.Between(mapping::PoseAt(poses, frame.stamp_ns)));
  }
  const robotio::PointList in_map =
      mapping::ScanPointsInMap(frames, offsets, mapping::RegistrationRig(rig, slam, mapping),
                               at_scan, mapping.voxel_filter_m);
  const robotio::PointList sparse = slam.registration_voxel_m > 0.0
                                        ? mapping::VoxelGridFilter(in_map, slam.registration_voxel_m)
                                        : in_map;
  return mapping::TransformedPoints(sparse, at_scan.Inverse().ToIsometry());
}

double AteRmse(const robotio::Trajectory& truth, const robotio::Trajectory& estimate) {
  const auto evaluation = mapping::EvaluateTrajectory(truth, estimate, {});
  return evaluation ? evaluation->ate_m.rmse : std::nan("");
}

}  // namespace

int main(int argc, char** argv) {
  std::string log, trajectory_file, out;
  std::vector<std::string> settings;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--log") log = argv[i + 1];
    if (key == "--trajectory") trajectory_file = argv[i + 1];
    if (key == "--settings") settings.emplace_back(argv[i + 1]);
    if (key == "--out") out = argv[i + 1];
  }
  if (log.empty() || trajectory_file.empty()) {
    Fail("usage: bench_loop_closure --log REC --trajectory TUM [--settings YAML]... [--out DIR]");
  }
  auto reader = robotio::RecordingReader::Open(log);
  if (!reader) Fail(reader.error().message);
  if (reader->ground_truth().empty()) Fail(log + ": no groundtruth.txt to compare with");
  auto trajectory = robotio::ReadTumTrajectory(trajectory_file);
  if (!trajectory) Fail(trajectory.error().message);
  if (trajectory->empty()) Fail(trajectory_file + ": no poses");
  const mapping::Trajectory2D poses = Planar(*trajectory);
  const mapping::Trajectory2D truth = Planar(reader->ground_truth());
  // The wheels and gyro for the odometry edges, dead-reckoned with the default motion
  // model (a pass run with other --motion settings had slightly other odometry).
  const mapping::Trajectory2D odometry =
      mapping::DeadReckon(reader->odometry(), reader->imu(), mapping::MotionModelConfig{});

  std::vector<mapping::SlamConfig> configs;
  if (settings.empty()) settings.emplace_back("");
  for (const std::string& file : settings) {
    if (file.empty()) {
      configs.emplace_back();
      continue;
    }
    auto config = mapping::LoadSlamConfig(file);
    if (!config) Fail(config.error().message);
    configs.push_back(*config);
  }
  const mapping::MappingConfig mapping_config;
  std::vector<mapping::LoopClosing> closings;
  for (const mapping::SlamConfig& config : configs) closings.emplace_back(config.loop_closure);

  // Every scan the trajectory has a pose for, in capture order.
  const robotio::Rig& rig = reader->rig();
  const app::RecordingScans grouped = app::GroupRecordingIntoScans(*reader, rig);
  const auto& entries = reader->depth_entries();
  const auto first = trajectory->front().stamp_ns, last = trajectory->back().stamp_ns;
  const auto tolerance = robotio::SecondsToNanos(0.001);
  std::size_t done = 0;
  for (const auto& scan : grouped.scans) {
    ++done;
    const std::int64_t stamp = grouped.capture_ns[scan.front()];
    if (stamp < first - tolerance || stamp > last + tolerance) continue;
    std::vector<robotio::DepthFrame> frames;
    for (std::size_t k : scan) {
      auto frame = reader->LoadDepth(entries[grouped.order[k]]);
      if (!frame) Fail(frame.error().message);
      frames.push_back(std::move(*frame));
    }
    const robotio::Pose2D pose = mapping::PoseAt(poses, stamp);
    const std::optional<robotio::Pose2D> at_odometry =
        odometry.empty() ? std::nullopt : std::optional(mapping::PoseAt(odometry, stamp));
    // One scan for all settings that build it alike.
    robotio::PointList points;
    const mapping::SlamConfig* built_for = nullptr;
    for (std::size_t c = 0; c < closings.size(); ++c) {
      if (built_for == nullptr ||
          built_for->registration_voxel_m != configs[c].registration_voxel_m ||
          built_for->registration_max_depth_m != configs[c].registration_max_depth_m) {
        points = RegisteredScan(frames, poses, rig, configs[c], mapping_config);
        built_for = &configs[c];
      }
      closings[c].Offer(stamp, pose, points, at_odometry);
    }
    if (done % 500 == 0 || done == grouped.scans.size()) {
      std::fprintf(stderr, "\rscans %zu / %zu", done, grouped.scans.size());
    }
  }
  std::fprintf(stderr, "\n");

  const double before = AteRmse(reader->ground_truth(), *trajectory);
  std::printf("%-28s %9s %6s %6s %7s %8s %8s %7s\n", "settings", "keyframes", "tried", "closed",
              "off>5cm", "ATE_in", "ATE_out", "close_s");
  for (std::size_t c = 0; c < closings.size(); ++c) {
    const auto start = std::chrono::steady_clock::now();
    const mapping::LoopClosureSummary summary = closings[c].Close();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    robotio::Trajectory corrected = *trajectory;
    for (robotio::StampedPose& p : corrected) {
      p.pose = closings[c].Correct(p.stamp_ns, robotio::Pose2D::FromIsometry(p.pose)).ToIsometry();
    }
    std::size_t off = 0;
    for (const mapping::LoopClosureAttempt& a : summary.attempts) {
      if (a.outcome != mapping::LoopClosureOutcome::kClosed) continue;
      const robotio::Pose2D true_relative = mapping::PoseAt(truth, a.older_stamp_ns)
                                                .Between(mapping::PoseAt(truth, a.newer_stamp_ns));
      if (std::hypot(a.measured.x - true_relative.x, a.measured.y - true_relative.y) > 0.05) ++off;
    }
    const std::string name = settings[c].empty() ? "defaults" : settings[c];
    std::printf("%-28s %9zu %6zu %6zu %7zu %8.4f %8.4f %7.2f\n", name.c_str(), summary.keyframes,
                summary.attempts.size(), summary.Count(mapping::LoopClosureOutcome::kClosed), off,
                before, AteRmse(reader->ground_truth(), corrected), seconds);
    if (!out.empty()) {
      std::filesystem::create_directories(out);
      const std::string n = std::to_string(c);
      const auto written = robotio::WriteTumTrajectory(corrected, out + "/trajectory_" + n + ".tum");
      if (!written) Fail(written.error().message);
      const auto csv = robotio::WriteFileAtomically(out + "/loop_closures_" + n + ".csv",
                                                    mapping::LoopClosureAttemptsCsv(summary.attempts));
      if (!csv) Fail(csv.error().message);
    }
  }
  return 0;
}
