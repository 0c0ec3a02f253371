#include "dynamap/mapping/TrajectoryEvaluation.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::mapping {

using robotio::Trajectory;

std::vector<std::pair<std::size_t, std::size_t>> AssociateStamps(const Trajectory& ground_truth,
                                                                  const Trajectory& estimate,
                                                                  double max_difference_s) {
  const std::int64_t limit_ns = robotio::SecondsToNanos(max_difference_s);
  // Candidates within the limit by a sliding window over the (sorted) estimate stamps;
  // sorting them by difference and taking them greedily is what associate.py does with
  // its all-pairs list, without the quadratic cost.
  std::vector<std::tuple<std::int64_t, std::size_t, std::size_t>> candidates;
  std::vector<std::size_t> order(estimate.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return estimate[a].stamp_ns < estimate[b].stamp_ns;
  });
  std::size_t window_start = 0;
  for (std::size_t g = 0; g < ground_truth.size(); ++g) {
    const std::int64_t t = ground_truth[g].stamp_ns;
    while (window_start < order.size() && estimate[order[window_start]].stamp_ns <= t - limit_ns)
      ++window_start;
    for (std::size_t k = window_start; k < order.size(); ++k) {
      const std::int64_t difference = estimate[order[k]].stamp_ns - t;
      if (difference >= limit_ns) break;
      candidates.emplace_back(std::abs(difference), g, order[k]);
    }
  }
  std::sort(candidates.begin(), candidates.end());
  std::vector<bool> gt_used(ground_truth.size(), false);
  std::vector<bool> est_used(estimate.size(), false);
  std::vector<std::pair<std::size_t, std::size_t>> matches;
  for (const auto& [difference, g, e] : candidates) {
    if (gt_used[g] || est_used[e]) continue;
    gt_used[g] = true;
    est_used[e] = true;
    matches.emplace_back(g, e);
  }
  std::sort(matches.begin(), matches.end(), [&](const auto& a, const auto& b) {
    return ground_truth[a.first].stamp_ns < ground_truth[b.first].stamp_ns;
  });
  return matches;
}

Eigen::Isometry3d AlignRigid(const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.matrix() = Eigen::umeyama(from, to, /*with_scaling=*/false);
  return T;
}

ErrorStatistics ComputeStatistics(std::vector<double> errors) {
  ErrorStatistics stats;
  if (errors.empty()) return stats;
  const double n = static_cast<double>(errors.size());
  double sum = 0.0;
  double sum_sq = 0.0;
  for (double e : errors) {
    sum += e;
    sum_sq += e * e;
  }
  stats.mean = sum / n;
  stats.rmse = std::sqrt(sum_sq / n);
  stats.std = std::sqrt(std::max(0.0, sum_sq / n - stats.mean * stats.mean));
  std::sort(errors.begin(), errors.end());
  stats.min = errors.front();
  stats.max = errors.back();
  const std::size_t mid = errors.size() / 2;
  stats.median = errors.size() % 2 == 1 ? errors[mid] : 0.5 * (errors[mid - 1] + errors[mid]);
  return stats;
}

namespace {

// Segments start at every associated pose and end at the first pose at least
// `segment_m` of ground-truth path further on; errors are normalised by that path length.
std::optional<RelativePoseError> ComputeRpe(const std::vector<Eigen::Isometry3d>& gt,
                                            const std::vector<Eigen::Isometry3d>& est,
                                            double segment_m) {
  std::vector<double> path(gt.size(), 0.0);
  for (std::size_t i = 1; i < gt.size(); ++i)
    path[i] = path[i - 1] + (gt[i].translation() - gt[i - 1].translation()).norm();
  RelativePoseError rpe;
  double trans_sum = 0.0;
  double rot_sum = 0.0;
  std::size_t j = 0;
  for (std::size_t i = 0; i < gt.size(); ++i) {
    j = std::max(j, i + 1);
    while (j < gt.size() && path[j] - path[i] < segment_m) ++j;
    if (j >= gt.size()) break;
    const double length = path[j] - path[i];
    const Eigen::Isometry3d gt_delta = gt[i].inverse() * gt[j];
    const Eigen::Isometry3d est_delta = est[i].inverse() * est[j];
    const Eigen::Isometry3d error = gt_delta.inverse() * est_delta;
    trans_sum += error.translation().norm() / length;
    rot_sum += Eigen::AngleAxisd(error.linear()).angle() * 180.0 / M_PI / length;
    ++rpe.segments;
  }
  if (rpe.segments == 0) return std::nullopt;
  rpe.trans_m_per_m = trans_sum / static_cast<double>(rpe.segments);
  rpe.rot_deg_per_m = rot_sum / static_cast<double>(rpe.segments);
  return rpe;
}

}  // namespace

std::optional<TrajectoryEvaluation> EvaluateTrajectory(const Trajectory& ground_truth,
                                                       const Trajectory& estimate,
                                                       const TrajectoryEvaluationConfig& config) {
  const auto matches = AssociateStamps(ground_truth, estimate, config.max_stamp_difference_s);
  if (matches.size() < (config.align ? 3u : 1u)) return std::nullopt;
  const auto n = static_cast<Eigen::Index>(matches.size());
  Eigen::Matrix3Xd gt_points(3, n);
  Eigen::Matrix3Xd est_points(3, n);
  std::vector<Eigen::Isometry3d> gt_poses;
  std::vector<Eigen::Isometry3d> est_poses;
  gt_poses.reserve(matches.size());
  est_poses.reserve(matches.size());
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto& [g, e] = matches[static_cast<std::size_t>(k)];
    gt_points.col(k) = ground_truth[g].pose.translation();
    est_points.col(k) = estimate[e].pose.translation();
    gt_poses.push_back(ground_truth[g].pose);
    est_poses.push_back(estimate[e].pose);
  }
  TrajectoryEvaluation result;
  result.pairs = matches.size();
  if (config.align) result.T_groundtruth_estimate = AlignRigid(est_points, gt_points);
  const Eigen::Matrix3Xd aligned = result.T_groundtruth_estimate * est_points;
  std::vector<double> errors(matches.size());
  for (Eigen::Index k = 0; k < n; ++k)
    errors[static_cast<std::size_t>(k)] = (aligned.col(k) - gt_points.col(k)).norm();
  result.ate_m = ComputeStatistics(std::move(errors));
  // Relative errors do not depend on a global alignment.
  result.rpe = ComputeRpe(gt_poses, est_poses, config.rpe_segment_m);
  return result;
}

}  // namespace dynamap::mapping
