#include "dynamap/mapping/LoopClosure.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "dynamap/mapping/Preprocessing.hpp"

namespace dynamap::mapping {
namespace {

double Distance(const robotio::Pose2D& a, const robotio::Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace

const char* LoopClosureOutcomeName(LoopClosureOutcome outcome) {
  switch (outcome) {
    case LoopClosureOutcome::kClosed:
      return "closed";
    case LoopClosureOutcome::kPoorFit:
      return "poor fit";
    case LoopClosureOutcome::kImplausible:
      return "implausible";
    case LoopClosureOutcome::kDropped:
      return "dropped";
  }
  return "closed";
}

LoopClosureConfig ParseLoopClosureConfig(robotio::ConfigNode& node) {
  LoopClosureConfig config;
  node.Read("enabled", &config.enabled);
  node.Read("keyframe_distance_m", &config.keyframe_distance_m, 0.01, 10.0);
  node.Read("keyframe_angle_rad", &config.keyframe_angle_rad, 0.01, 3.2);
  node.Read("min_time_gap_s", &config.min_time_gap_s, 0.0, 1e6);
  node.Read("search_radius_m", &config.search_radius_m, 0.0, 20.0);
  node.Read("local_map_half_width", &config.local_map_half_width, 0, 100);
  node.Read("local_map_voxel_m", &config.local_map_voxel_m, 0.0, 1.0);
  node.Read("min_inlier_ratio", &config.min_inlier_ratio, 0.0, 1.0);
  node.Read("max_fitness_rmse_m", &config.max_fitness_rmse_m, 1e-4, 1.0);
  node.Read("max_correction_m", &config.max_correction_m, 0.0, 10.0);
  node.Read("max_correction_rad", &config.max_correction_rad, 0.0, 3.2);
  node.Read("sequence_sigma_m", &config.sequence_sigma_m, 1e-6, 1.0);
  node.Read("sequence_sigma_per_sqrt_m", &config.sequence_sigma_per_sqrt_m, 0.0, 1.0);
  node.Read("sequence_sigma_rad", &config.sequence_sigma_rad, 1e-7, 1.0);
  node.Read("sequence_sigma_per_sqrt_rad", &config.sequence_sigma_per_sqrt_rad, 0.0, 1.0);
  node.Read("closure_information_scale", &config.closure_information_scale, 0.0, 1e12);
  if (auto registration = node.OptionalChild("registration")) {
    config.registration = ParseRegistrationConfig(*registration);
  }
  return config;
}

std::size_t LoopClosureSummary::Count(LoopClosureOutcome outcome) const {
  return static_cast<std::size_t>(std::count_if(
      attempts.begin(), attempts.end(),
      [&](const LoopClosureAttempt& attempt) { return attempt.outcome == outcome; }));
}

LoopClosing::LoopClosing(LoopClosureConfig config) : config_(std::move(config)) {}

bool LoopClosing::Offer(std::int64_t stamp_ns, const robotio::Pose2D& pose,
                        const robotio::PointList& scan) {
  if (!keyframes_.empty()) {
    const robotio::Pose2D step = last_pose_.Between(pose);
    driven_since_keyframe_ += std::hypot(step.x, step.y);
    turned_since_keyframe_ += std::abs(step.theta);
  }
  last_pose_ = pose;
  const bool due = keyframes_.empty() || driven_since_keyframe_ >= config_.keyframe_distance_m ||
                   turned_since_keyframe_ >= config_.keyframe_angle_rad;
  if (!due || scan.empty()) return false;
  keyframes_.push_back({stamp_ns, pose, pose, scan});
  driven_since_keyframe_ = 0.0;
  turned_since_keyframe_ = 0.0;
  closed_ = false;
  return true;
}

robotio::PointList LoopClosing::LocalMap(std::size_t centre) const {
  const auto half = static_cast<std::size_t>(config_.local_map_half_width);
  const std::size_t first = centre > half ? centre - half : 0;
  const std::size_t last = std::min(keyframes_.size() - 1, centre + half);
  const robotio::Pose2D& origin = keyframes_[centre].pose;
  robotio::PointList points;
  for (std::size_t k = first; k <= last; ++k) {
    const robotio::PointList placed =
        TransformedPoints(keyframes_[k].scan, origin.Between(keyframes_[k].pose).ToIsometry());
    points.insert(points.end(), placed.begin(), placed.end());
  }
  return config_.local_map_voxel_m > 0.0 ? VoxelGridFilter(points, config_.local_map_voxel_m)
                                         : points;
}

PoseGraphEdge LoopClosing::SequenceEdge(std::size_t from, std::size_t to) const {
  PoseGraphEdge edge;
  edge.from = from;
  edge.to = to;
  edge.measured = keyframes_[from].pose.Between(keyframes_[to].pose);
  const double sigma_m = config_.sequence_sigma_m +
                         config_.sequence_sigma_per_sqrt_m *
                             std::sqrt(std::hypot(edge.measured.x, edge.measured.y));
  const double sigma_rad =
      config_.sequence_sigma_rad +
      config_.sequence_sigma_per_sqrt_rad * std::sqrt(std::abs(edge.measured.theta));
  edge.information = Eigen::Vector3d(1.0 / (sigma_m * sigma_m), 1.0 / (sigma_m * sigma_m),
                                     1.0 / (sigma_rad * sigma_rad))
                         .asDiagonal();
  return edge;
}

LoopClosureSummary LoopClosing::Close() {
  LoopClosureSummary summary;
  summary.keyframes = keyframes_.size();
  closed_ = true;
  for (Keyframe& k : keyframes_) k.corrected = k.pose;
  if (keyframes_.size() < 2) return summary;

  std::vector<PoseGraphEdge> edges;
  for (std::size_t k = 1; k < keyframes_.size(); ++k) edges.push_back(SequenceEdge(k - 1, k));
  const std::size_t sequence_edges = edges.size();
  std::vector<std::size_t> closure_attempt;  // Per closure edge, its attempt.

  Registration registration(config_.registration);
  std::size_t target_of = keyframes_.size();  // Keyframe whose local map is the target.
  const auto gap_ns = static_cast<std::int64_t>(config_.min_time_gap_s * 1e9);
  for (std::size_t j = 0; j < keyframes_.size(); ++j) {
    // The nearest keyframe old enough to make a loop.
    std::size_t best = keyframes_.size();
    double best_distance = config_.search_radius_m;
    for (std::size_t i = 0; i < j && keyframes_[j].stamp_ns - keyframes_[i].stamp_ns >= gap_ns;
         ++i) {
      const double d = Distance(keyframes_[i].pose, keyframes_[j].pose);
      if (d <= best_distance) {
        best_distance = d;
        best = i;
      }
    }
    if (best == keyframes_.size()) continue;
    if (target_of != best) {
      registration.SetTarget(LocalMap(best));
      target_of = best;
    }
    const robotio::Pose2D guess = keyframes_[best].pose.Between(keyframes_[j].pose);
    const RegistrationResult result = registration.Align(keyframes_[j].scan, guess.ToIsometry());
    LoopClosureAttempt attempt{keyframes_[best].stamp_ns, keyframes_[j].stamp_ns, guess,
                               robotio::Pose2D::FromIsometry(result.T_target_source),
                               result.fitness_rmse_m, result.inlier_ratio,
                               PlanarStructure(result.planar_information),
                               LoopClosureOutcome::kClosed};
    const robotio::Pose2D correction = guess.Between(attempt.measured);
    if (!result.converged || result.inlier_ratio < config_.min_inlier_ratio ||
        result.fitness_rmse_m > config_.max_fitness_rmse_m) {
      attempt.outcome = LoopClosureOutcome::kPoorFit;
    } else if (std::hypot(correction.x, correction.y) > config_.max_correction_m ||
               std::abs(correction.theta) > config_.max_correction_rad) {
      attempt.outcome = LoopClosureOutcome::kImplausible;
    } else {
      PoseGraphEdge edge;
      edge.from = best;
      edge.to = j;
      edge.measured = attempt.measured;
      // The registration's information is in the target (older keyframe's) frame with
      // the yaw about the source origin: the same frame and yaw as the edge's error.
      edge.information = result.planar_information * config_.closure_information_scale;
      edge.closure = true;
      edges.push_back(edge);
      closure_attempt.push_back(summary.attempts.size());
    }
    summary.attempts.push_back(attempt);
  }
  if (closure_attempt.empty()) return summary;

  std::vector<robotio::Pose2D> poses;
  for (const Keyframe& k : keyframes_) poses.push_back(k.pose);
  summary.graph = OptimizePoseGraph(&poses, edges);
  for (std::size_t e : summary.graph.dropped) {
    summary.attempts[closure_attempt[e - sequence_edges]].outcome = LoopClosureOutcome::kDropped;
  }
  for (std::size_t k = 0; k < keyframes_.size(); ++k) {
    keyframes_[k].corrected = poses[k];
    summary.largest_correction_m =
        std::max(summary.largest_correction_m, Distance(poses[k], keyframes_[k].pose));
  }
  return summary;
}

robotio::Pose2D LoopClosing::Correct(std::int64_t stamp_ns, const robotio::Pose2D& pose) const {
  if (!closed_ || keyframes_.empty()) return pose;
  const auto after = std::lower_bound(
      keyframes_.begin(), keyframes_.end(), stamp_ns,
      [](const Keyframe& k, std::int64_t stamp) { return k.stamp_ns < stamp; });
  auto moved = [&](const Keyframe& k) { return k.corrected.Compose(k.pose.Between(pose)); };
  if (after == keyframes_.begin()) return moved(*after);
  if (after == keyframes_.end()) return moved(keyframes_.back());
  const Keyframe& before = *std::prev(after);
  const double span = static_cast<double>(after->stamp_ns - before.stamp_ns);
  const double s = span > 0.0 ? static_cast<double>(stamp_ns - before.stamp_ns) / span : 0.0;
  return robotio::Interpolate(moved(before), moved(*after), s);
}

}  // namespace dynamap::mapping
