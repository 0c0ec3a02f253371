#include "dynamap/mapping/WallHeading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <Eigen/Core>

#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::mapping {
namespace {

constexpr double kQuarter = M_PI / 2.0;

std::int64_t CellKey(std::int64_t i, std::int64_t j) { return (i << 32) ^ (j & 0xffffffff); }

struct Gathered {
  int count = 0;
  double mean = 0.0;  // Of the pieces' offsets from the centre (rad).
};

Gathered GatherAround(const std::vector<LinePiece>& pieces, double centre, double gate) {
  Gathered gathered;
  double sum = 0.0;
  for (const LinePiece& piece : pieces) {
    const double offset = WrapQuarter(piece.angle_rad - centre);
    if (std::abs(offset) > gate) continue;
    sum += offset;
    ++gathered.count;
  }
  if (gathered.count > 0) gathered.mean = sum / gathered.count;
  return gathered;
}

}  // namespace

WallHeadingConfig ParseWallHeadingConfig(robotio::ConfigNode& node) {
  WallHeadingConfig config;
  node.Read("enabled", &config.enabled);
  node.Read("sigma_rad", &config.sigma_rad, 1e-5, 1.0);
  node.Read("gate_rad", &config.gate_rad, 1e-3, 0.5);
  node.Read("cell_m", &config.cell_m, 0.02, 1.0);
  node.Read("min_height_m", &config.min_height_m, -10.0, 10.0);
  node.Read("max_height_m", &config.max_height_m, -10.0, 10.0);
  if (config.max_height_m <= config.min_height_m) {
    node.Fail("max_height_m", "must be above min_height_m");
  }
  node.Read("max_thickness_ratio", &config.max_thickness_ratio, 0.0, 1.0);
  node.Read("min_aligned_cells", &config.min_aligned_cells, 1, 1'000'000);
  node.Read("min_aligned_share", &config.min_aligned_share, 0.0, 1.0);
  node.Read("learn_scans", &config.learn_scans, 1, 1'000'000);
  node.Read("holds_heading_s", &config.holds_heading_s, 0.0, 3600.0);
  return config;
}

double WrapQuarter(double angle) {
  double wrapped = std::fmod(angle + kQuarter / 2.0, kQuarter);
  if (wrapped < 0.0) wrapped += kQuarter;
  return wrapped - kQuarter / 2.0;
}

std::vector<LinePiece> LinePieces(const robotio::PointList& points,
                                  const WallHeadingConfig& config) {
  std::vector<Eigen::Vector2d> flat;
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  const double inverse_cell = 1.0 / config.cell_m;
  for (const auto& p : points) {
    if (!p.allFinite() || p.z() < config.min_height_m || p.z() > config.max_height_m) continue;
    cells[CellKey(static_cast<std::int64_t>(std::floor(p.x() * inverse_cell)),
                  static_cast<std::int64_t>(std::floor(p.y() * inverse_cell)))]
        .push_back(static_cast<int>(flat.size()));
    flat.emplace_back(p.x(), p.y());
  }
  // Each fit takes the points within a circle round the cell's own mean: a circle centred
  // on the line cuts a noisy line the same on both sides, where a square window cuts it
  // unevenly at its corners whenever the line is not along the window's axes.
  const double radius = 1.5 * config.cell_m;
  const double min_spread = 0.5 * config.cell_m;  // Along the piece, standard deviation.
  std::vector<LinePiece> pieces;
  for (const auto& [key, members] : cells) {
    if (members.size() < 2) continue;
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (int m : members) centre += flat[static_cast<std::size_t>(m)];
    centre /= static_cast<double>(members.size());
    const std::int64_t i = key >> 32;
    const std::int64_t j = static_cast<std::int32_t>(key & 0xffffffff);
    int n = 0;
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    Eigen::Matrix2d outer = Eigen::Matrix2d::Zero();
    for (std::int64_t di = -2; di <= 2; ++di) {
      for (std::int64_t dj = -2; dj <= 2; ++dj) {
        const auto other = cells.find(CellKey(i + di, j + dj));
        if (other == cells.end()) continue;
        for (int m : other->second) {
          const Eigen::Vector2d d = flat[static_cast<std::size_t>(m)] - centre;
          if (d.squaredNorm() > radius * radius) continue;
          ++n;
          sum += d;
          outer += d * d.transpose();
        }
      }
    }
    if (n < 6) continue;
    const Eigen::Vector2d mean = sum / n;
    const Eigen::Matrix2d covariance = outer / n - mean * mean.transpose();
    const double cxx = covariance(0, 0);
    const double cxy = covariance(0, 1);
    const double cyy = covariance(1, 1);
    const double half_trace = 0.5 * (cxx + cyy);
    const double root = std::sqrt(std::max(0.0, 0.25 * (cxx - cyy) * (cxx - cyy) + cxy * cxy));
    const double along = half_trace + root;
    const double across = std::max(0.0, half_trace - root);
    if (along <= min_spread * min_spread) continue;
    if (std::sqrt(across / along) > config.max_thickness_ratio) continue;
    pieces.push_back({WrapQuarter(0.5 * std::atan2(2.0 * cxy, cxx - cyy))});
  }
  return pieces;
}

std::optional<double> AlignedDirection(const std::vector<LinePiece>& pieces, double around,
                                       const WallHeadingConfig& config) {
  if (pieces.empty()) return std::nullopt;
  double centre = WrapQuarter(around);
  Gathered gathered;
  for (int round = 0; round < 3; ++round) {
    gathered = GatherAround(pieces, centre, config.gate_rad);
    if (gathered.count == 0) return std::nullopt;
    centre = WrapQuarter(centre + gathered.mean);
  }
  if (gathered.count < config.min_aligned_cells ||
      gathered.count < config.min_aligned_share * static_cast<double>(pieces.size())) {
    return std::nullopt;
  }
  return centre;
}

std::optional<double> DominantDirection(const std::vector<LinePiece>& pieces,
                                        const WallHeadingConfig& config) {
  double c = 0.0;
  double s = 0.0;
  for (const LinePiece& piece : pieces) {
    c += std::cos(4.0 * piece.angle_rad);
    s += std::sin(4.0 * piece.angle_rad);
  }
  if (c == 0.0 && s == 0.0) return std::nullopt;
  return AlignedDirection(pieces, std::atan2(s, c) / 4.0, config);
}

std::optional<double> WallHeading::Measure(const robotio::PointList& points,
                                           double estimated_heading) {
  const std::vector<LinePiece> pieces = LinePieces(points, config_);
  if (!axes_known()) {
    const std::optional<double> direction = DominantDirection(pieces, config_);
    if (direction) {
      // The axis in the map frame: the scan's wall direction turned by the heading.
      const double axis = WrapQuarter(estimated_heading + *direction);
      sum_cos_ += std::cos(4.0 * axis);
      sum_sin_ += std::sin(4.0 * axis);
      ++learnt_;
    }
    return std::nullopt;
  }
  const double expected = WrapQuarter(axes_rad() - estimated_heading);
  const std::optional<double> direction = AlignedDirection(pieces, expected, config_);
  if (!direction) return std::nullopt;
  return robotio::WrapAngle(estimated_heading + WrapQuarter(expected - *direction));
}

double WallHeading::axes_rad() const { return std::atan2(sum_sin_, sum_cos_) / 4.0; }

}  // namespace dynamap::mapping
