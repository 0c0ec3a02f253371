#include "dynamap/mapping/LoopClosure.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <utility>

#include "dynamap/mapping/Preprocessing.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::mapping {
namespace {

double Distance(const robotio::Pose2D& a, const robotio::Pose2D& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

// Keyframe `to` measured from the one before, with independent x/y and yaw noise.
PoseGraphEdge EdgeFromPrevious(std::size_t to, const robotio::Pose2D& measured, double sigma_m,
                               double sigma_rad) {
  PoseGraphEdge edge;
  edge.from = to - 1;
  edge.to = to;
  edge.measured = measured;
  edge.information = Eigen::Vector3d(1.0 / (sigma_m * sigma_m), 1.0 / (sigma_m * sigma_m),
                                     1.0 / (sigma_rad * sigma_rad))
                         .asDiagonal();
  return edge;
}

double Driven(const robotio::Pose2D& step) { return std::hypot(step.x, step.y); }

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
  node.Read("revisit_candidates", &config.revisit_candidates, 1, 100);
  node.Read("heading_weight_m_per_rad", &config.heading_weight_m_per_rad, 0.0, 100.0);
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
  node.Read("held_sequence_sigma_rad", &config.held_sequence_sigma_rad, 1e-7, 1.0);
  node.Read("held_sequence_sigma_per_sqrt_rad", &config.held_sequence_sigma_per_sqrt_rad, 0.0,
            1.0);
  node.Read("odometry_sigma_m", &config.odometry_sigma_m, 0.0, 1.0);
  node.Read("odometry_sigma_per_sqrt_m", &config.odometry_sigma_per_sqrt_m, 0.0, 1.0);
  node.Read("odometry_sigma_rad", &config.odometry_sigma_rad, 1e-6, 10.0);
  node.Read("closure_information_scale", &config.closure_information_scale, 0.0, 1e12);
  node.Read("correct_while_running", &config.correct_while_running);
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

std::string LoopClosureAttemptsCsv(const std::vector<LoopClosureAttempt>& attempts) {
  std::string csv =
      "older_stamp_s,newer_stamp_s,guess_x,guess_y,guess_theta,measured_x,measured_y,"
      "measured_theta,fitness_rmse_m,inlier_ratio,structure,outcome\n";
  char line[512];
  for (const LoopClosureAttempt& a : attempts) {
    std::snprintf(line, sizeof(line), "%.6f,%.6f,%.5f,%.5f,%.6f,%.5f,%.5f,%.6f,%.5f,%.4f,%.5f,%s\n",
                  robotio::NanosToSeconds(a.older_stamp_ns),
                  robotio::NanosToSeconds(a.newer_stamp_ns), a.guess.x, a.guess.y, a.guess.theta,
                  a.measured.x, a.measured.y, a.measured.theta, a.fitness_rmse_m, a.inlier_ratio,
                  a.structure, LoopClosureOutcomeName(a.outcome));
    csv += line;
  }
  return csv;
}

LoopClosing::LoopClosing(LoopClosureConfig config) : config_(std::move(config)) {}

bool LoopClosing::Offer(std::int64_t stamp_ns, const robotio::Pose2D& pose,
                        const robotio::PointList& scan,
                        const std::optional<robotio::Pose2D>& odometry,
                        bool heading_measured) {
  if (!keyframes_.empty()) {
    const robotio::Pose2D step = last_pose_.Between(pose);
    driven_since_keyframe_ += std::hypot(step.x, step.y);
    turned_since_keyframe_ += std::abs(step.theta);
  }
  last_pose_ = pose;
  const bool due = keyframes_.empty() || driven_since_keyframe_ >= config_.keyframe_distance_m ||
                   turned_since_keyframe_ >= config_.keyframe_angle_rad;
  if (!due || scan.empty()) return false;
  keyframes_.push_back({stamp_ns, pose, pose, pose, scan, odometry, heading_measured});
  driven_since_keyframe_ = 0.0;
  turned_since_keyframe_ = 0.0;
  return true;
}

robotio::PointList LoopClosing::LocalMap(std::size_t centre) const {
  const auto half = static_cast<std::size_t>(config_.local_map_half_width);
  const std::size_t first = centre > half ? centre - half : 0;
  const std::size_t last = std::min(keyframes_.size() - 1, centre + half);
  const robotio::Pose2D& origin = keyframes_[centre].corrected;
  robotio::PointList points;
  for (std::size_t k = first; k <= last; ++k) {
    const robotio::PointList placed = TransformedPoints(
        keyframes_[k].scan, origin.Between(keyframes_[k].corrected).ToIsometry());
    points.insert(points.end(), placed.begin(), placed.end());
  }
  return config_.local_map_voxel_m > 0.0 ? VoxelGridFilter(points, config_.local_map_voxel_m)
                                         : points;
}

PoseGraphEdge LoopClosing::SequenceEdge(std::size_t to) const {
  // Both in the frame SLAM placed the scans between them in.
  const robotio::Pose2D measured = keyframes_[to - 1].pose_after.Between(keyframes_[to].pose);
  const bool held = keyframes_[to - 1].heading_measured && keyframes_[to].heading_measured;
  const double sigma_rad = held ? config_.held_sequence_sigma_rad : config_.sequence_sigma_rad;
  const double sigma_per_sqrt_rad =
      held ? config_.held_sequence_sigma_per_sqrt_rad : config_.sequence_sigma_per_sqrt_rad;
  return EdgeFromPrevious(
      to, measured,
      config_.sequence_sigma_m + config_.sequence_sigma_per_sqrt_m * std::sqrt(Driven(measured)),
      sigma_rad + sigma_per_sqrt_rad * std::sqrt(std::abs(measured.theta)));
}

std::optional<PoseGraphEdge> LoopClosing::OdometryEdge(std::size_t to) const {
  const auto& from_odometry = keyframes_[to - 1].odometry;
  const auto& to_odometry = keyframes_[to].odometry;
  if (config_.odometry_sigma_m <= 0.0 || !from_odometry || !to_odometry) return std::nullopt;
  const robotio::Pose2D measured = from_odometry->Between(*to_odometry);
  return EdgeFromPrevious(
      to, measured,
      config_.odometry_sigma_m + config_.odometry_sigma_per_sqrt_m * std::sqrt(Driven(measured)),
      config_.odometry_sigma_rad);
}

// The registrations of the local maps used lately (Close() walks the keyframes in
// order, so consecutive revisits mostly look at the same older places).
class LoopClosing::TargetCache {
 public:
  explicit TargetCache(const LoopClosing& closing) : closing_(closing) {}
  const Registration& For(std::size_t centre) {
    auto found = built_.find(centre);
    if (found != built_.end()) return *found->second;
    if (built_.size() >= kCapacity) built_.erase(built_.begin());  // Oldest keyframe.
    auto registration = std::make_unique<Registration>(closing_.config_.registration);
    registration->SetTarget(closing_.LocalMap(centre));
    return *built_.emplace(centre, std::move(registration)).first->second;
  }

 private:
  static constexpr std::size_t kCapacity = 32;
  const LoopClosing& closing_;
  std::map<std::size_t, std::unique_ptr<Registration>> built_;
};

std::vector<std::size_t> LoopClosing::RevisitCandidates(std::size_t newer) const {
  const auto gap_ns = static_cast<std::int64_t>(config_.min_time_gap_s * 1e9);
  const Keyframe& j = keyframes_[newer];
  std::vector<std::pair<double, std::size_t>> near;  // (score, keyframe)
  for (std::size_t i = 0; i < newer && j.stamp_ns - keyframes_[i].stamp_ns >= gap_ns; ++i) {
    const double d = Distance(keyframes_[i].corrected, j.corrected);
    if (d > config_.search_radius_m) continue;
    const double turn = std::abs(robotio::WrapAngle(j.corrected.theta - keyframes_[i].corrected.theta));
    near.emplace_back(d + config_.heading_weight_m_per_rad * turn, i);
  }
  std::sort(near.begin(), near.end());
  // Each from another stretch of the path: local maps that share no keyframe.
  const auto apart = static_cast<std::size_t>(2 * config_.local_map_half_width);
  std::vector<std::size_t> chosen;
  for (const auto& [score, i] : near) {
    if (chosen.size() >= static_cast<std::size_t>(config_.revisit_candidates)) break;
    const bool distinct = std::all_of(chosen.begin(), chosen.end(), [&](std::size_t c) {
      return (i > c ? i - c : c - i) > apart;
    });
    if (distinct) chosen.push_back(i);
  }
  return chosen;
}

std::vector<LoopClosing::Revisit> LoopClosing::TryRevisits(std::size_t newer,
                                                           TargetCache* targets) const {
  const Keyframe& j = keyframes_[newer];
  std::vector<Revisit> revisits;
  for (std::size_t older : RevisitCandidates(newer)) {
    const Registration& registration = targets->For(older);
    const robotio::Pose2D guess = keyframes_[older].corrected.Between(j.corrected);
    const RegistrationResult result = registration.Align(j.scan, guess.ToIsometry());
    Revisit revisit{{keyframes_[older].stamp_ns, j.stamp_ns, guess,
                     robotio::Pose2D::FromIsometry(result.T_target_source), result.fitness_rmse_m,
                     result.inlier_ratio, PlanarStructure(result.planar_information),
                     LoopClosureOutcome::kClosed},
                    std::nullopt};
    LoopClosureAttempt& attempt = revisit.attempt;
    const robotio::Pose2D correction = guess.Between(attempt.measured);
    if (!result.converged || result.inlier_ratio < config_.min_inlier_ratio ||
        result.fitness_rmse_m > config_.max_fitness_rmse_m) {
      attempt.outcome = LoopClosureOutcome::kPoorFit;
    } else if (std::hypot(correction.x, correction.y) > config_.max_correction_m ||
               std::abs(correction.theta) > config_.max_correction_rad) {
      attempt.outcome = LoopClosureOutcome::kImplausible;
    } else {
      PoseGraphEdge edge;
      edge.from = older;
      edge.to = newer;
      edge.measured = attempt.measured;
      // The registration's information is in the target (older keyframe's) frame with
      // the yaw about the source origin: the same frame and yaw as the edge's error.
      edge.information = result.planar_information * config_.closure_information_scale;
      edge.closure = true;
      revisit.edge = edge;
    }
    revisits.push_back(std::move(revisit));
  }
  return revisits;
}

void LoopClosing::Solve(const std::vector<PoseGraphEdge>& closures,
                        const std::vector<std::size_t>& closure_attempts,
                        LoopClosureSummary* summary) {
  std::vector<PoseGraphEdge> edges;
  for (std::size_t k = 1; k < keyframes_.size(); ++k) {
    edges.push_back(SequenceEdge(k));
    if (const auto odometry = OdometryEdge(k)) edges.push_back(*odometry);
  }
  const std::size_t sequence_edges = edges.size();
  edges.insert(edges.end(), closures.begin(), closures.end());
  std::vector<robotio::Pose2D> poses;
  for (const Keyframe& k : keyframes_) poses.push_back(k.corrected);
  summary->graph = OptimizePoseGraph(&poses, edges);
  for (std::size_t e : summary->graph.dropped) {
    summary->attempts[closure_attempts[e - sequence_edges]].outcome = LoopClosureOutcome::kDropped;
  }
  for (std::size_t k = 0; k < keyframes_.size(); ++k) {
    keyframes_[k].corrected = poses[k];
    summary->largest_correction_m =
        std::max(summary->largest_correction_m, Distance(poses[k], keyframes_[k].pose));
  }
  closed_ = true;
}

LoopClosureSummary LoopClosing::Close() {
  LoopClosureSummary summary;
  summary.keyframes = keyframes_.size();
  if (keyframes_.size() < 2) return summary;
  std::vector<PoseGraphEdge> closures;
  std::vector<std::size_t> closure_attempts;  // Per closure, its attempt.
  TargetCache targets(*this);
  for (std::size_t j = 0; j < keyframes_.size(); ++j) {
    for (const Revisit& revisit : TryRevisits(j, &targets)) {
      if (revisit.edge) {
        closures.push_back(*revisit.edge);
        closure_attempts.push_back(summary.attempts.size());
      }
      summary.attempts.push_back(revisit.attempt);
    }
  }
  if (!closures.empty()) Solve(closures, closure_attempts, &summary);
  return summary;
}

std::optional<robotio::Pose2D> LoopClosing::CloseNewest() {
  online_.keyframes = keyframes_.size();
  if (keyframes_.empty()) return std::nullopt;
  const std::size_t newest = keyframes_.size() - 1;
  TargetCache targets(*this);
  bool closed = false;
  for (const Revisit& revisit : TryRevisits(newest, &targets)) {
    online_.attempts.push_back(revisit.attempt);
    if (!revisit.edge) continue;
    online_closures_.push_back(*revisit.edge);
    online_closure_attempts_.push_back(online_.attempts.size() - 1);
    closed = true;
  }
  if (!closed) return std::nullopt;
  const robotio::Pose2D before = keyframes_[newest].corrected;
  Solve(online_closures_, online_closure_attempts_, &online_);
  // A closure the graph dropped stays out of later solves.
  for (std::size_t c = online_closures_.size(); c-- > 0;) {
    if (online_.attempts[online_closure_attempts_[c]].outcome == LoopClosureOutcome::kDropped) {
      online_closures_.erase(online_closures_.begin() + static_cast<std::ptrdiff_t>(c));
      online_closure_attempts_.erase(online_closure_attempts_.begin() +
                                     static_cast<std::ptrdiff_t>(c));
    }
  }
  Keyframe& k = keyframes_[newest];
  const robotio::Pose2D correction = k.corrected.Compose(before.Inverse());
  k.pose_after = correction.Compose(k.pose_after);
  last_pose_ = correction.Compose(last_pose_);
  return correction;
}

robotio::Pose2D LoopClosing::Correct(std::int64_t stamp_ns, const robotio::Pose2D& pose) const {
  if (!closed_ || keyframes_.empty()) return pose;
  const auto after = std::lower_bound(
      keyframes_.begin(), keyframes_.end(), stamp_ns,
      [](const Keyframe& k, std::int64_t stamp) { return k.stamp_ns < stamp; });
  // A scan is in the frame of the keyframe before it as it stood after that keyframe
  // (pose_after) and of the one after it as offered (pose).
  auto from_before = [&](const Keyframe& k) { return k.corrected.Compose(k.pose_after.Between(pose)); };
  auto from_after = [&](const Keyframe& k) { return k.corrected.Compose(k.pose.Between(pose)); };
  if (after == keyframes_.begin()) return from_after(*after);
  if (after == keyframes_.end()) return from_before(keyframes_.back());
  const Keyframe& before = *std::prev(after);
  const double span = static_cast<double>(after->stamp_ns - before.stamp_ns);
  const double s = span > 0.0 ? static_cast<double>(stamp_ns - before.stamp_ns) / span : 0.0;
  return robotio::Interpolate(from_before(before), from_after(*after), s);
}

}  // namespace dynamap::mapping
