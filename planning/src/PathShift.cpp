#include "dynamap/planning/PathShift.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynamap::planning {

namespace {

// Footprint centres every `sample_m` along the path from `from_m` to `to_m` (arc length).
std::vector<Eigen::Vector2d> SamplePath(const std::vector<Eigen::Vector2d>& path, double from_m,
                                        double to_m, double sample_m) {
  std::vector<Eigen::Vector2d> samples;
  double start = 0.0;  // Arc length at the segment's start.
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Eigen::Vector2d d = path[i + 1] - path[i];
    const double length = d.norm();
    if (length < 1e-9) continue;
    const double first = std::ceil(std::max(from_m, start) / sample_m) * sample_m;
    for (double s = first; s <= std::min(to_m, start + length); s += sample_m) {
      samples.push_back(path[i] + d * ((s - start) / length));
    }
    start += length;
  }
  return samples;
}

// Arc length of the point of `path` nearest to `p`.
double Project(const std::vector<Eigen::Vector2d>& path, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  double best_s = 0.0;
  double start = 0.0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i) {
    const Eigen::Vector2d d = path[i + 1] - path[i];
    const double length = d.norm();
    const double t =
        length < 1e-9 ? 0.0 : std::clamp((p - path[i]).dot(d) / (length * length), 0.0, 1.0);
    const double distance = (path[i] + t * d - p).norm();
    if (distance < best) {
      best = distance;
      best_s = start + t * length;
    }
    start += length;
  }
  return best_s;
}

}  // namespace

Eigen::Vector2d PathShiftTarget(const std::vector<Eigen::Vector2d>& path_map,
                                const Eigen::Vector2d& robot_on_path,
                                const std::vector<Eigen::Vector2d>& obstacles_map,
                                double footprint_m, const PathShiftConfig& config) {
  const Eigen::Vector2d none = Eigen::Vector2d::Zero();
  if (path_map.size() < 2 || obstacles_map.empty()) return none;
  const double s0 = Project(path_map, robot_on_path);
  const std::vector<Eigen::Vector2d> samples =
      SamplePath(path_map, s0 - config.behind_m, s0 + config.ahead_m, config.sample_m);
  if (samples.empty()) return none;
  // Per sample, the obstacles any tried shift could bring within comfort.
  const double reach = footprint_m + config.comfort_m + config.max_shift_m + config.step_m;
  std::vector<std::vector<Eigen::Vector2d>> near(samples.size());
  bool any = false;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    for (const Eigen::Vector2d& o : obstacles_map) {
      if ((o - samples[i]).squaredNorm() <= reach * reach) near[i].push_back(o - samples[i]);
    }
    any = any || !near[i].empty();
  }
  if (!any) return none;
  // Clearance of the shifted stretch, capped at comfort.
  const auto clearance = [&](const Eigen::Vector2d& shift) {
    double worst = config.comfort_m;
    for (const auto& points : near) {
      for (const Eigen::Vector2d& o : points) {
        worst = std::min(worst, (o - shift).norm() - footprint_m);
      }
    }
    return worst;
  };
  const double unshifted = clearance(none);
  if (unshifted >= config.comfort_m) return none;
  Eigen::Vector2d best = none;
  double best_score = unshifted;
  double best_clearance = unshifted;
  const int n = static_cast<int>(std::floor(config.max_shift_m / config.step_m));
  for (int i = -n; i <= n; ++i) {
    for (int j = -n; j <= n; ++j) {
      const Eigen::Vector2d shift(i * config.step_m, j * config.step_m);
      const double size = shift.norm();
      if ((i == 0 && j == 0) || size > config.max_shift_m + 1e-9) continue;
      const double free = clearance(shift);
      const double score = free - config.shift_cost * size;
      if (score > best_score) {
        best_score = score;
        best_clearance = free;
        best = shift;
      }
    }
  }
  // Only a shift that frees the footprint: what no shift within reach clears (a person's
  // trail across the path) is the collision guard's.
  return best_score >= unshifted + config.min_gain_m && best_clearance >= 0.0 ? best : none;
}

Eigen::Vector2d PathShift::Update(const std::vector<Eigen::Vector2d>& path_map,
                                  const Eigen::Vector2d& robot_map,
                                  const std::vector<Eigen::Vector2d>& obstacles_map,
                                  double footprint_m, double dt_s) {
  const Eigen::Vector2d target =
      config_.enabled ? PathShiftTarget(path_map, robot_map - shift_, obstacles_map,
                                        footprint_m, config_)
                      : Eigen::Vector2d::Zero();
  const Eigen::Vector2d step = target - shift_;
  const double largest = config_.rate_mps * dt_s;
  shift_ += step.norm() <= largest ? step : step.normalized() * largest;
  return shift_;
}

}  // namespace dynamap::planning
