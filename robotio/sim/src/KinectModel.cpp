#include "dynamap/robotio/sim/KinectModel.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace dynamap::robotio::sim {

std::uint64_t HashKey(std::uint64_t a, std::uint64_t b) {
  // splitmix64 finaliser over a combination of both words.
  std::uint64_t z = a * 0x9E3779B97F4A7C15ULL + b + 0x632BE59BD9B4E019ULL;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

double UniformFromKey(std::uint64_t key) {
  return static_cast<double>(HashKey(key, 0x5851F42D4C957F2DULL) >> 11) * 0x1.0p-53;
}

namespace {

constexpr int kGaussianBits = 16;

// Inverse standard normal CDF at the centres of 2^16 equal-probability bins (Newton on
// erfc). A table lookup per pixel instead of log/sqrt/cos keeps the noise pass cheaper
// than the ray casting; the tails are cut at about 4.3 sigma, which removes a negligible
// share of the variance.
const std::vector<float>& GaussianTable() {
  static const std::vector<float> table = [] {
    const int n = 1 << kGaussianBits;
    std::vector<float> t(static_cast<std::size_t>(n));
    double x = -4.5;
    for (int i = 0; i < n; ++i) {
      const double p = (i + 0.5) / n;
      for (int iteration = 0; iteration < 50; ++iteration) {
        const double cdf = 0.5 * std::erfc(-x / std::sqrt(2.0));
        const double pdf = std::exp(-0.5 * x * x) / std::sqrt(2.0 * M_PI);
        const double dx = (cdf - p) / pdf;
        x -= dx;
        if (std::abs(dx) < 1e-12) break;
      }
      t[static_cast<std::size_t>(i)] = static_cast<float>(x);
    }
    return t;
  }();
  return table;
}

}  // namespace

double GaussianFromKey(std::uint64_t key) {
  const std::uint64_t h = HashKey(key, 0x9E3779B97F4A7C15ULL);
  return GaussianTable()[static_cast<std::size_t>(h >> (64 - kGaussianBits))];
}

std::uint16_t MeasureDepth(const KinectModelConfig& config, double z_m, double cos_incidence,
                           bool at_edge, std::uint64_t key) {
  if (!(z_m > 0.0) || z_m > config.far_limit_m) return 0;
  if (!config.enabled) return static_cast<std::uint16_t>(std::lround(z_m * 1000.0));
  // One 64-bit hash per draw: this runs for every pixel of every frame.
  const std::uint64_t h = HashKey(key, 0x2545F4914F6CDD1DULL);
  double p_drop = config.random_dropout_probability;
  // acos only for the few pixels near grazing incidence (grazing_start_deg >= 60).
  if (cos_incidence < 0.5 && cos_incidence < std::cos(config.grazing_start_deg * M_PI / 180.0)) {
    const double incidence_deg = std::acos(std::clamp(cos_incidence, 0.0, 1.0)) * 180.0 / M_PI;
    p_drop = std::max(p_drop, (incidence_deg - config.grazing_start_deg) /
                                  (config.grazing_full_deg - config.grazing_start_deg));
  }
  if (at_edge) p_drop = std::max(p_drop, config.edge_dropout_probability);
  if (p_drop > 0.0 && static_cast<double>(h >> 11) * 0x1.0p-53 < p_drop) return 0;
  // Noise in inverse depth: a constant sigma there is noise_coeff * z^2 in depth. The
  // disparity and millimetre roundings add their own variance (step^2 / 12 each), so the
  // Gaussian part is reduced to keep the total at the model.
  const double step = config.disparity_step;
  const double mm_term = 1e-6 / 12.0 / (z_m * z_m * z_m * z_m);
  const double sigma_w = std::sqrt(std::max(
      0.0, config.noise_coeff * config.noise_coeff - step * step / 12.0 - mm_term));
  const double w = 1.0 / z_m + sigma_w * GaussianFromKey(h);
  const double w_q = step > 0.0 ? std::round(w / step) * step : w;
  if (w_q <= 0.0) return 0;
  const double z = 1.0 / w_q;
  if (z > config.far_limit_m || z * 1000.0 > 65535.0) return 0;
  return static_cast<std::uint16_t>(std::lround(z * 1000.0));
}

}  // namespace dynamap::robotio::sim
