// Runs the SLAM loop over a recording in one of the thesis's run modes (2.3): playback
// (every scan, as fast as possible) or simulate (recorded pace, late scans dropped).
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/mapping/CameraTracker.hpp"
#include "dynamap/mapping/MotionModel.hpp"
#include "dynamap/mapping/SlamLoop.hpp"
#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::app {

enum class RunMode { kPlayback, kSimulate };

struct SlamRunOptions {
  mapping::SlamConfig slam;
  mapping::MappingConfig mapping;
  mapping::MotionModelConfig motion;
  mapping::CameraTrackerConfig tracker;  // For recordings without odometry.
  RunMode mode = RunMode::kPlayback;
  // The recorded ground-truth path instead of wheels + gyro as odometry: what is left of
  // the error is the registration's own (and the map's feedback on it).
  bool odometry_from_ground_truth = false;
};

// What SLAM did with one scan (slam_scans.csv): the odometry prediction, the pose it kept
// and the registration behind the difference.
struct SlamScanRecord {
  std::int64_t stamp_ns = 0;
  robotio::Pose2D predicted;
  robotio::Pose2D pose;
  // "previous" or "map" (or "keyframes" when tracking without odometry); empty when
  // nothing was registered.
  std::string reference;
  bool accepted = false;
  bool reference_rebuilt = false;
  double fitness_rmse_m = 0.0;
  double inlier_ratio = 0.0;
  int iterations = 0;
  // Smallest / largest eigenvalue of the planar information: how well the scan pins x, y
  // and yaw (near 0 along a bare corridor).
  double structure = 0.0;
  std::size_t scan_points = 0;
  // The heading the walls said (SlamConfig::wall_heading), when one was fused.
  std::optional<double> wall_theta;
};

struct SlamRunResult {
  robotio::Trajectory trajectory;   // T_map_base at each processed scan's capture time.
  robotio::Trajectory frame_poses;  // T_map_base at each processed frame's capture time.
  robotio::Trajectory odometry;     // Odometry + gyro alone, at the same scan stamps.
  // No odometry: the camera was tracked by registration alone (mapping::CameraTracker),
  // in 6-DoF; `odometry` is empty and the map frame is the first scan's pose.
  bool tracking_only = false;
  std::size_t keyframes = 0;       // Tracking only: scans that joined the local map.
  std::size_t track_restarts = 0;  // Tracking only: times the track was lost.
  std::size_t frames_processed = 0;
  std::size_t frames_dropped = 0;   // Simulate mode: not taken in time.
  std::size_t registrations_accepted = 0;
  std::size_t registrations_rejected = 0;  // Attempted, not applied.
  std::vector<SlamScanRecord> scans;  // One per processed scan.
  // With loop closure (SlamConfig::loop_closure): `trajectory` and `frame_poses` are the
  // corrected ones, this is what the pass itself gave, and the summary says what closed.
  robotio::Trajectory trajectory_before_loop_closure;
  std::optional<mapping::LoopClosureSummary> loop_closure;
  double loop_closure_s = 0.0;  // Wall time of finding the closures and solving.
  mapping::ReferenceStrategy reference = mapping::ReferenceStrategy::kCombined;  // Used.
  // Wall time per processed scan of each stage (s).
  std::vector<double> preprocess_s, register_s, update_s, total_s;
};

// The per-scan records as CSV, one header line, SI units and radians.
[[nodiscard]] std::string ScanRecordsCsv(const std::vector<SlamScanRecord>& scans);

// Errors (an unreadable frame) are reported through Expected. `progress` gets the
// fraction of scans done.
[[nodiscard]] robotio::Expected<SlamRunResult> RunSlam(
    const robotio::RecordingReader& reader, const SlamRunOptions& options,
    const std::function<void(double)>& progress);

}  // namespace dynamap::app
