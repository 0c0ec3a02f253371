// Loop closure: keyframes (scans every half metre or so, with the poses SLAM gave them),
// each registered against the local maps of older keyframes near it, and a planar pose
// graph (PoseGraph.hpp) that bends the trajectory so that places seen twice agree. SLAM's
// scan-to-map loop cannot correct a map once written (thesis Algorithm 4 has no such
// step); this is where revisits do. Over a finished pass (Close(): dynamap map, and a
// mission when it ends) or as the robot goes (CloseNewest(): a mission with
// correct_while_running), then moving SLAM's pose at each closure.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/mapping/PoseGraph.hpp"
#include "dynamap/mapping/Registration.hpp"
#include "dynamap/robotio/ConfigReader.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::mapping {

struct LoopClosureConfig {
  bool enabled = true;
  double keyframe_distance_m = 0.5;  // A new keyframe after this much driving ...
  double keyframe_angle_rad = 0.35;  // ... or this much turning.
  // A loop: a keyframe near (x/y, by SLAM's poses) one at least this much older.
  double min_time_gap_s = 20.0;
  double search_radius_m = 1.5;
  // Older keyframes registered against per revisit, each from another stretch of the
  // path (local maps that share no keyframe), in the order of distance +
  // heading_weight × heading difference: a revisit facing another way overlaps little
  // with the nearest keyframe's view. Every one that fits is a closure. On the replayed
  // office mission (seed 1) the nearest keyframe within 1 m left 0.136 m ATE (31 of 273
  // revisits closed); 3 by view within 1 m 0.080 m (53 of 472), within 1.5 m 0.078 m
  // (62 of 666) (docs/RESULTS.md). 1 and 0 m/rad: the nearest keyframe only.
  int revisit_candidates = 3;
  double heading_weight_m_per_rad = 0.5;
  // The older keyframe's local map: it and this many keyframes on each side, placed by
  // SLAM's poses (consistent over such a short stretch), thinned to the scan's voxel.
  int local_map_half_width = 3;
  double local_map_voxel_m = 0.1;
  // A closure is kept when its registration converged this well and moves the newer
  // keyframe relative to the older one by no more than SLAM could have got wrong. On the
  // office tour 0.6 / 0.045 m closed 18 of 101 revisits and gave 0.035 m ATE over the
  // keyframes; 0.7 / 0.04 m closed 14 (0.038 m), 0.5 / 0.05 m closed 25 (0.041 m, more
  // of them wrong) (docs/RESULTS.md).
  double min_inlier_ratio = 0.6;
  double max_fitness_rmse_m = 0.045;
  double max_correction_m = 0.5;
  double max_correction_rad = 0.1;
  // Noise of SLAM's relative pose between consecutive keyframes (the sequence edges):
  // position per √m driven plus a floor, heading per √rad turned plus a floor.
  double sequence_sigma_m = 0.002;
  double sequence_sigma_per_sqrt_m = 0.01;
  double sequence_sigma_rad = 0.0005;
  double sequence_sigma_per_sqrt_rad = 0.005;
  // The same heading sigmas between two keyframes whose heading the walls measured
  // (Offer's `heading_measured`, SlamConfig::wall_heading): that heading is known
  // independently of the map, so a closure pulling the position must not turn the
  // stretch between them. With the walls on and the sequence sigmas above, a closure
  // turned the stretch the walls had held straight (office tour 0.047 m before loop
  // closure, 0.068 after; 0.047 with these; docs/RESULTS.md).
  double held_sequence_sigma_rad = 0.00002;
  double held_sequence_sigma_per_sqrt_rad = 0.0002;
  // Odometry edges: between consecutive keyframes also the wheels' and gyro's relative
  // pose, when the keyframes were offered with their odometry pose. SLAM's sequence edges
  // carry what the registrations got wrong while the map ahead was new (a few cm along a
  // few metres, docs/RESULTS.md), the wheels only their scale and slip; the graph weighs
  // both. Position sigma per edge: floor + per √m driven; heading sigma per edge (large:
  // the gyro's left-over bias, the heading stays SLAM's). odometry_sigma_m 0: no edges.
  // On the office tour (default pass replayed) 0.052 m -> 0.018 m; 2 mm + 5 mm/√m 0.030,
  // 1 mm + 1 mm/√m 0.020 (docs/RESULTS.md). Wheels whose scale is off by more than the
  // simulated RMP's 0.1 % want a larger sigma.
  double odometry_sigma_m = 0.001;
  double odometry_sigma_per_sqrt_m = 0.003;
  double odometry_sigma_rad = 0.01;
  // A closure's information is the registration's planar information (mean over its
  // inlier pairs, so a corridor's axis gets almost none) times this: effective number of
  // independent pairs / (point-to-plane noise)².
  double closure_information_scale = 25.0 / (0.01 * 0.01);
  RegistrationConfig registration;  // ICP for the closures.
  // In a mission: each closure moves SLAM's pose as soon as it is found (CloseNewest)
  // instead of all of them correcting the trajectory once at the end (Close). Off: on the
  // office (seed 1, revisits against the nearest keyframe only) the closures taken as
  // they came left the mission's ATE at 0.92 m, against 0.15 m closed at the end; a
  // wrong one is applied before any later one can contradict it, and the map goes on
  // from the wrong pose (docs/RESULTS.md).
  bool correct_while_running = false;
};

// Reads a "loop_closure:" mapping; unknown keys are errors.
[[nodiscard]] LoopClosureConfig ParseLoopClosureConfig(robotio::ConfigNode& node);

// What became of a revisit tried.
enum class LoopClosureOutcome {
  kClosed,       // Into the pose graph and kept there.
  kPoorFit,      // Not converged, too few inliers or too large an RMS.
  kImplausible,  // Would move the pair further than the gate allows.
  kDropped,      // Into the graph, dropped there: it disagreed with the rest.
};
// "closed", "poor fit", "implausible", "dropped" (loop_closures.csv).
[[nodiscard]] const char* LoopClosureOutcomeName(LoopClosureOutcome outcome);

// One revisit tried: the older keyframe's local map against the newer keyframe's scan.
struct LoopClosureAttempt {
  std::int64_t older_stamp_ns = 0;
  std::int64_t newer_stamp_ns = 0;
  robotio::Pose2D guess;     // Newer in older's frame, by SLAM's poses.
  robotio::Pose2D measured;  // The same by the registration.
  double fitness_rmse_m = 0.0;
  double inlier_ratio = 0.0;
  double structure = 0.0;  // Smallest / largest eigenvalue of its planar information.
  LoopClosureOutcome outcome = LoopClosureOutcome::kClosed;
};

struct LoopClosureSummary {
  std::size_t keyframes = 0;
  PoseGraphSummary graph;
  double largest_correction_m = 0.0;  // Of any keyframe, by the optimisation.
  std::vector<LoopClosureAttempt> attempts;  // Every revisit registered.
  // Attempts with this outcome.
  [[nodiscard]] std::size_t Count(LoopClosureOutcome outcome) const;
};

// The revisits tried, as CSV (loop_closures.csv): stamps of the older and newer keyframe,
// SLAM's guess and the registration's measurement of the newer in the older's frame, the
// fit and what became of it.
[[nodiscard]] std::string LoopClosureAttemptsCsv(const std::vector<LoopClosureAttempt>& attempts);

class LoopClosing {
 public:
  explicit LoopClosing(LoopClosureConfig config);

  // A scan SLAM placed at `pose` (T_map_base) with its registered points (base frame);
  // kept as a keyframe when it is the first or the robot moved far enough since the
  // last. Scans come in capture order. True when kept.
  // `odometry`: the wheels' and gyro's pose at the same time, for the odometry edges.
  // `heading_measured`: the heading of `pose` was measured independently of the map
  // (SlamLoop::heading_held_by_walls()); the sequence edge between two such keyframes
  // holds their relative heading (held_sequence_sigma_rad).
  bool Offer(std::int64_t stamp_ns, const robotio::Pose2D& pose, const robotio::PointList& scan,
             const std::optional<robotio::Pose2D>& odometry = std::nullopt,
             bool heading_measured = false);

  // Finds the closures, optimises the graph and keeps the corrected keyframe poses.
  LoopClosureSummary Close();

  // Online, right after Offer() kept a keyframe: tries that keyframe's revisits and, when
  // any closes, solves the graph over every keyframe and the closures kept so far.
  // Returns how the newest keyframe moved (T_map_base ← correction ∘ T_map_base; none
  // when nothing closed). The caller must move its pose by it (SlamLoop::ApplyCorrection):
  // the poses offered from then on are taken to be in the corrected frame.
  std::optional<robotio::Pose2D> CloseNewest();
  // What CloseNewest() tried so far, the last solve and the largest correction it made.
  [[nodiscard]] const LoopClosureSummary& online() const { return online_; }

  // `pose` of a scan at `stamp_ns` moved by the correction of the keyframes around it
  // (interpolated in time between the one before and the one after). Before any closure,
  // or without keyframes, `pose` unchanged.
  [[nodiscard]] robotio::Pose2D Correct(std::int64_t stamp_ns, const robotio::Pose2D& pose) const;
  [[nodiscard]] std::size_t keyframes() const { return keyframes_.size(); }

 private:
  struct Keyframe {
    std::int64_t stamp_ns = 0;
    robotio::Pose2D pose;        // SLAM's, as offered.
    robotio::Pose2D pose_after;  // The same in the frame of the scans after it (moved by
                                 // the correction CloseNewest() made at it, if any).
    robotio::Pose2D corrected;   // Best estimate: `pose` until a solve moves it.
    robotio::PointList scan;     // Base frame.
    std::optional<robotio::Pose2D> odometry;  // Wheels and gyro, when offered.
    bool heading_measured = false;            // By the walls, as offered.
  };
  // The older keyframe `centre`'s local map in its own frame.
  [[nodiscard]] robotio::PointList LocalMap(std::size_t centre) const;
  [[nodiscard]] PoseGraphEdge SequenceEdge(std::size_t to) const;  // From the one before.
  // The same by odometry; none when off or either keyframe came without odometry.
  [[nodiscard]] std::optional<PoseGraphEdge> OdometryEdge(std::size_t to) const;
  // Older keyframes to register keyframe `newer` against (old enough to make a loop,
  // within the search radius), best first.
  [[nodiscard]] std::vector<std::size_t> RevisitCandidates(std::size_t newer) const;
  // Keyframe `newer` against each of its candidates: the attempt and, when it is
  // plausible, its graph edge. `targets` keeps the local maps' registrations built.
  struct Revisit {
    LoopClosureAttempt attempt;
    std::optional<PoseGraphEdge> edge;
  };
  class TargetCache;
  std::vector<Revisit> TryRevisits(std::size_t newer, TargetCache* targets) const;
  // Solves the sequence edges with `closures`, from the current estimates; marks the
  // attempts of dropped closures (indices into `summary->attempts`) and keeps the result.
  void Solve(const std::vector<PoseGraphEdge>& closures,
             const std::vector<std::size_t>& closure_attempts, LoopClosureSummary* summary);

  LoopClosureConfig config_;
  std::vector<Keyframe> keyframes_;
  double driven_since_keyframe_ = 0.0;
  double turned_since_keyframe_ = 0.0;
  robotio::Pose2D last_pose_;
  bool closed_ = false;  // A solve has moved the estimates.
  // Online: the closures kept so far and their attempts' indices in online_.attempts.
  LoopClosureSummary online_;
  std::vector<PoseGraphEdge> online_closures_;
  std::vector<std::size_t> online_closure_attempts_;
};

}  // namespace dynamap::mapping
