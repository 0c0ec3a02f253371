#include "cli/SlamRun.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <optional>

#include "cli/RecordingScans.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::app {
namespace {

using Clock = std::chrono::steady_clock;

// What one scan gave, from either estimator.
struct ScanOutcome {
  SlamScanRecord record;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // T_map_base at the scan.
  std::vector<Eigen::Isometry3d> frame_poses;              // One per frame of the scan.
  robotio::Pose2D odometry;  // Odometry pose at the scan (odometry runs only).
  bool registered = false, accepted = false;
  double preprocess_s = 0.0, register_s = 0.0, update_s = 0.0;
};

void FillRegistration(const mapping::RegistrationResult& registration, SlamScanRecord* record) {
  record->fitness_rmse_m = registration.fitness_rmse_m;
  record->inlier_ratio = registration.inlier_ratio;
  record->iterations = registration.iterations;
  record->structure = mapping::PlanarStructure(registration.planar_information);
}

ScanOutcome ProcessWithOdometry(mapping::SlamLoop& slam, const mapping::Trajectory2D& dead_reckoning,
                                const std::vector<robotio::DepthFrame>& frames) {
  std::vector<robotio::Pose2D> odometry;
  for (const robotio::DepthFrame& frame : frames) {
    odometry.push_back(mapping::PoseAt(dead_reckoning, frame.stamp_ns));
  }
  const mapping::SlamStep step = slam.ProcessScan(frames, odometry);
  ScanOutcome out;
  out.record.stamp_ns = frames.front().stamp_ns;
  out.record.predicted = step.predicted;
  out.record.pose = step.pose;
  out.record.reference = step.registered ? step.reference : "";
  out.record.accepted = step.accepted;
  out.record.reference_rebuilt = step.reference_rebuilt;
  FillRegistration(step.registration, &out.record);
  out.record.scan_points = step.scan_points;
  out.record.wall_theta = step.wall_heading_rad;
  out.pose = step.pose.ToIsometry();
  for (const robotio::Pose2D& at : odometry) {
    out.frame_poses.push_back(step.pose.Compose(odometry.front().Between(at)).ToIsometry());
  }
  out.odometry = odometry.front();
  out.registered = step.registered;
  out.accepted = step.accepted;
  out.preprocess_s = step.preprocess_s;
  out.register_s = step.register_s;
  out.update_s = step.update_s;
  return out;
}

ScanOutcome ProcessByRegistration(mapping::CameraTracker& tracker,
                                  const std::vector<robotio::DepthFrame>& frames) {
  const mapping::TrackerStep step = tracker.Track(frames);
  ScanOutcome out;
  out.record.stamp_ns = step.stamp_ns;
  out.record.predicted = robotio::Pose2D::FromIsometry(step.predicted);
  out.record.pose = robotio::Pose2D::FromIsometry(step.pose);
  out.record.reference = step.registered ? "keyframes" : "";
  out.record.accepted = step.accepted;
  out.record.reference_rebuilt = step.keyframe;
  FillRegistration(step.registration, &out.record);
  out.record.scan_points = step.scan_points;
  out.pose = step.pose;
  out.frame_poses.assign(frames.size(), step.pose);
  out.registered = step.registered;
  out.accepted = step.accepted;
  out.preprocess_s = step.preprocess_s;
  out.register_s = step.register_s;
  return out;
}

}  // namespace

robotio::Expected<SlamRunResult> RunSlam(const robotio::RecordingReader& reader,
                                         const SlamRunOptions& options,
                                         const std::function<void(double)>& progress) {
  SlamRunResult result;
  result.reference = options.slam.reference;
  const robotio::Rig& rig = reader.rig();
  const auto& entries = reader.depth_entries();
  const RecordingScans grouped = GroupRecordingIntoScans(reader, rig);
  const std::vector<std::size_t>& order = grouped.order;
  const auto& scans = grouped.scans;

  // Without odometry (a TUM RGB-D sequence, a rig carried by hand) registration alone
  // tracks the camera in 6-DoF.
  const bool tracking_only = !options.odometry_from_ground_truth && reader.odometry().empty();
  mapping::Trajectory2D dead_reckoning;
  if (options.odometry_from_ground_truth) {
    if (reader.ground_truth().empty()) {
      return robotio::Error{reader.dir() + ": no groundtruth.txt to use as odometry"};
    }
    for (const robotio::StampedPose& g : reader.ground_truth()) {
      dead_reckoning.push_back({g.stamp_ns, robotio::Pose2D::FromIsometry(g.pose)});
    }
  } else if (!tracking_only) {
    dead_reckoning = mapping::DeadReckon(reader.odometry(), reader.imu(), options.motion);
  }
  if (!tracking_only && dead_reckoning.empty()) {
    return robotio::Error{reader.dir() + ": no odometry readings"};
  }
  std::optional<mapping::SlamLoop> slam;
  std::optional<mapping::CameraTracker> tracker;
  if (tracking_only) {
    tracker.emplace(options.tracker, rig);
  } else {
    slam.emplace(options.slam, options.mapping, rig);
  }
  result.tracking_only = tracking_only;
  std::optional<mapping::LoopClosing> loop_closing;
  if (slam && options.slam.loop_closure.enabled) loop_closing.emplace(options.slam.loop_closure);

  // Simulate mode: a clock at the recording's pace that the SLAM work advances; a scan
  // is taken when SLAM is free, and only the newest one that has arrived by then.
  std::int64_t sim_clock_ns = 0;
  auto ready_ns = [&](const std::vector<std::size_t>& scan) {
    std::int64_t ready = 0;
    for (std::size_t k : scan) ready = std::max(ready, entries[order[k]].received_ns);
    return ready;
  };
  for (std::size_t s = 0; s < scans.size(); ++s) {
    if (options.mode == RunMode::kSimulate) {
      sim_clock_ns = std::max(sim_clock_ns, ready_ns(scans[s]));
      if (s + 1 < scans.size() && ready_ns(scans[s + 1]) <= sim_clock_ns) {
        result.frames_dropped += scans[s].size();
        continue;
      }
    }
    std::vector<robotio::DepthFrame> frames;
    for (std::size_t k : scans[s]) {
      auto frame = reader.LoadDepth(entries[order[k]]);
      if (!frame) return frame.error();
      frames.push_back(std::move(*frame));
    }
    const auto start = Clock::now();
    const ScanOutcome step = slam ? ProcessWithOdometry(*slam, dead_reckoning, frames)
                                  : ProcessByRegistration(*tracker, frames);
    const double total = std::chrono::duration<double>(Clock::now() - start).count();
    if (options.mode == RunMode::kSimulate) sim_clock_ns += robotio::SecondsToNanos(total);

    result.frames_processed += frames.size();
    if (step.accepted) {
      ++result.registrations_accepted;
    } else if (step.registered) {
      ++result.registrations_rejected;
    }
    result.preprocess_s.push_back(step.preprocess_s);
    result.register_s.push_back(step.register_s);
    result.update_s.push_back(step.update_s);
    result.total_s.push_back(total);
    result.scans.push_back(step.record);
    result.trajectory.push_back({step.record.stamp_ns, step.pose});
    if (slam) result.odometry.push_back(robotio::ToStampedPose(step.record.stamp_ns, step.odometry));
    for (std::size_t k = 0; k < frames.size(); ++k) {
      result.frame_poses.push_back({frames[k].stamp_ns, step.frame_poses[k]});
    }
    if (loop_closing) {
      loop_closing->Offer(step.record.stamp_ns, step.record.pose, slam->last_registered_scan(),
                          step.odometry, slam->heading_held_by_walls());
    }
    if (progress) progress(static_cast<double>(s + 1) / static_cast<double>(scans.size()));
  }
  std::sort(result.frame_poses.begin(), result.frame_poses.end(),
            [](const auto& a, const auto& b) { return a.stamp_ns < b.stamp_ns; });
  if (loop_closing) {
    const auto start = Clock::now();
    result.loop_closure = loop_closing->Close();
    result.loop_closure_s = std::chrono::duration<double>(Clock::now() - start).count();
    result.trajectory_before_loop_closure = result.trajectory;
    auto correct = [&](robotio::Trajectory* trajectory) {
      for (robotio::StampedPose& p : *trajectory) {
        p.pose = loop_closing->Correct(p.stamp_ns, robotio::Pose2D::FromIsometry(p.pose)).ToIsometry();
      }
    };
    correct(&result.trajectory);
    correct(&result.frame_poses);
  }
  if (tracker) {
    result.keyframes = tracker->keyframes();
    result.track_restarts = tracker->restarts();
  }
  return result;
}

std::string ScanRecordsCsv(const std::vector<SlamScanRecord>& scans) {
  std::string csv =
      "stamp_s,predicted_x,predicted_y,predicted_theta,x,y,theta,reference,accepted,"
      "reference_rebuilt,fitness_rmse_m,inlier_ratio,iterations,structure,scan_points,"
      "wall_theta\n";
  char line[512];
  for (const SlamScanRecord& r : scans) {
    const bool registered = !r.reference.empty();
    char wall[32] = "";
    if (r.wall_theta) std::snprintf(wall, sizeof(wall), "%.6f", *r.wall_theta);
    std::snprintf(line, sizeof(line),
                  "%.6f,%.5f,%.5f,%.6f,%.5f,%.5f,%.6f,%s,%d,%d,%.5f,%.4f,%d,%.5f,%zu,%s\n",
                  robotio::NanosToSeconds(r.stamp_ns), r.predicted.x, r.predicted.y,
                  r.predicted.theta, r.pose.x, r.pose.y, r.pose.theta,
                  registered ? r.reference.c_str() : "none", r.accepted ? 1 : 0,
                  r.reference_rebuilt ? 1 : 0, registered ? r.fitness_rmse_m : 0.0,
                  r.inlier_ratio, r.iterations, r.structure, r.scan_points, wall);
    csv += line;
  }
  return csv;
}

}  // namespace dynamap::app
