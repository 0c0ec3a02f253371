// Trajectory accuracy as the TUM RGB-D benchmark defines it (Sturm et al. 2012): stamp
// association, absolute trajectory error with optional rigid alignment, and relative pose
// error per metre travelled (DESIGN.md, Evaluation: ate_rmse_m, rpe_*; thesis 5.4).
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::mapping {

struct TrajectoryEvaluationConfig {
  double max_stamp_difference_s = 0.02;  // s, pairs further apart in time are not matched.
  bool align = false;  // Rigid (rotation + translation, no scale) alignment before ATE.
  double rpe_segment_m = 1.0;  // m of ground-truth path per relative-pose segment.
};

// Index pairs (ground truth, estimate) ordered by ground-truth stamp. Like the benchmark's
// associate.py: candidates closer than the limit are taken greedily, closest first, each
// stamp used at most once.
[[nodiscard]] std::vector<std::pair<std::size_t, std::size_t>> AssociateStamps(
    const robotio::Trajectory& ground_truth, const robotio::Trajectory& estimate,
    double max_difference_s);

// Rigid transform (no scale) that best maps `from` onto `to` in the least-squares sense
// (Horn 1987 / Umeyama 1991); columns are corresponding points. Needs ≥ 3 points.
[[nodiscard]] Eigen::Isometry3d AlignRigid(const Eigen::Matrix3Xd& from,
                                           const Eigen::Matrix3Xd& to);

struct ErrorStatistics {
  double rmse = 0.0;
  double mean = 0.0;
  double median = 0.0;
  double std = 0.0;  // Population standard deviation, as the benchmark prints it.
  double min = 0.0;
  double max = 0.0;
};
[[nodiscard]] ErrorStatistics ComputeStatistics(std::vector<double> errors);

struct RelativePoseError {
  std::size_t segments = 0;
  double trans_m_per_m = 0.0;   // Mean translational error / ground-truth path length.
  double rot_deg_per_m = 0.0;   // Mean rotation angle error (deg) / ground-truth path length.
};

struct TrajectoryEvaluation {
  std::size_t pairs = 0;
  ErrorStatistics ate_m;  // m, position errors after the optional alignment.
  Eigen::Isometry3d T_groundtruth_estimate = Eigen::Isometry3d::Identity();  // Alignment.
  std::optional<RelativePoseError> rpe;  // Absent when the path is shorter than a segment.
};

// nullopt when fewer than 3 pairs associate (or 1 without alignment).
[[nodiscard]] std::optional<TrajectoryEvaluation> EvaluateTrajectory(
    const robotio::Trajectory& ground_truth, const robotio::Trajectory& estimate,
    const TrajectoryEvaluationConfig& config);

}  // namespace dynamap::mapping
