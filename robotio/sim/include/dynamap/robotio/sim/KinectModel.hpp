// The Kinect v1 depth error model (Khoshelham & Oude Elberink 2012, thesis 5.1): axial
// noise sigma(z) = 1.425e-3 z^2, quantisation in disparity (steps of about 2.85e-3 z^2),
// dropouts at grazing incidence and depth discontinuities, millimetre output.
#pragma once

#include <cstdint>

namespace dynamap::robotio::sim {

struct KinectModelConfig {
  bool enabled = true;                   // false: exact depth (reference renders, tests).
  double noise_coeff = 1.425e-3;         // 1/m, total axial sigma(z) = noise_coeff * z^2,
                                         // quantisation included.
  double disparity_step = 2.85e-3;       // 1/m, inverse-depth step: z steps of step * z^2.
  double far_limit_m = 8.0;              // m, farthest reported depth; the Kinect reports
                                         // beyond the rig's reliable max_range_m.
  double grazing_start_deg = 75.0;       // deg incidence where dropouts begin (60..89) ...
  double grazing_full_deg = 87.0;        // ... deg incidence where every pixel drops out.
  double edge_jump_ratio = 0.04;         // Relative depth jump to a 4-neighbour that marks
                                         // a discontinuity.
  double edge_dropout_probability = 0.6;  // Of a pixel on a discontinuity.
  double random_dropout_probability = 0.002;  // Of any pixel.
};

// Counter-based randomness: the same key always gives the same numbers, so rendering in
// any thread order is deterministic for a seed.
[[nodiscard]] std::uint64_t HashKey(std::uint64_t a, std::uint64_t b);
[[nodiscard]] double UniformFromKey(std::uint64_t key);  // [0, 1)
[[nodiscard]] double GaussianFromKey(std::uint64_t key);  // N(0, 1)

// Measured depth in mm (0 = dropout) for a surface at true depth z_m seen at the given
// incidence (cosine between ray and surface normal), `at_edge` on a discontinuity.
[[nodiscard]] std::uint16_t MeasureDepth(const KinectModelConfig& config, double z_m,
                                         double cos_incidence, bool at_edge, std::uint64_t key);

}  // namespace dynamap::robotio::sim
