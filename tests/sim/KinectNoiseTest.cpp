#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "SimTestWorlds.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/sim/DepthRenderer.hpp"

namespace dynamap::robotio::sim {
namespace {

// Renders a wall seen at 35 deg incidence around distance z, with and without the noise
// model, and returns the standard deviation of (measured - true) / (1.425e-3 z^2).
double NormalisedNoiseSigma(double z) {
  const World world = testing::MustParse(testing::WallWorldYaml(0.5 + z * std::cos(35 * M_PI / 180)));
  DepthRenderer renderer(world, 2);
  const Intrinsics k = Intrinsics{}.Scaled(160, 120);
  // Yawed so the depth varies across the image: the samples cover every quantisation phase.
  const Eigen::Isometry3d T = MountPose({0.5, 0, 1.2}, {0, 0, 35 * M_PI / 180});
  KinectModelConfig exact;
  exact.enabled = false;
  KinectModelConfig noisy;
  noisy.random_dropout_probability = 0.0;
  noisy.edge_dropout_probability = 0.0;
  const RenderedImage truth = renderer.Render(T, k, 0.5, exact, 0);
  double sum = 0.0, sum_sq = 0.0;
  int n = 0;
  for (std::uint64_t frame = 1; frame <= 20; ++frame) {
    const RenderedImage image = renderer.Render(T, k, 0.5, noisy, frame);
    for (int v = 30; v < 90; ++v) {
      for (int u = 40; u < 120; ++u) {
        const double z_true = truth.depth.At(u, v) * 1e-3;
        const double z_meas = image.depth.At(u, v) * 1e-3;
        if (z_true <= 0.0 || z_meas <= 0.0 || std::abs(z_true - z) > 0.25 * z) continue;
        // The exact render is rounded to mm too; compare against the unrounded geometry
        // by using the model at the true depth.
        const double r = (z_meas - z_true) / (1.425e-3 * z_true * z_true);
        sum += r;
        sum_sq += r * r;
        ++n;
      }
    }
  }
  EXPECT_GT(n, 10000);
  const double mean = sum / n;
  return std::sqrt(sum_sq / n - mean * mean);
}

TEST(KinectNoise, AxialSigmaMatchesTheModelAt1m) { EXPECT_NEAR(NormalisedNoiseSigma(1.0), 1.0, 0.1); }
TEST(KinectNoise, AxialSigmaMatchesTheModelAt2m) { EXPECT_NEAR(NormalisedNoiseSigma(2.0), 1.0, 0.1); }
TEST(KinectNoise, AxialSigmaMatchesTheModelAt3m) { EXPECT_NEAR(NormalisedNoiseSigma(3.0), 1.0, 0.1); }

TEST(KinectNoise, DepthIsQuantisedInDisparitySteps) {
  KinectModelConfig model;
  model.random_dropout_probability = 0.0;
  // At 3 m the disparity step is about 2.85e-3 * 9 = 25.6 mm: few distinct values appear.
  std::set<std::uint16_t> values;
  for (std::uint64_t key = 0; key < 2000; ++key) values.insert(MeasureDepth(model, 3.0, 1.0, false, key));
  EXPECT_LE(values.size(), 8u);
  EXPECT_GE(values.size(), 2u);
}

TEST(KinectNoise, GrazingSurfacesAndRangeLimitsDropOut) {
  KinectModelConfig model;
  int dropped = 0;
  for (std::uint64_t key = 0; key < 1000; ++key) {
    if (MeasureDepth(model, 2.0, std::cos(88.0 * M_PI / 180.0), false, key) == 0) ++dropped;
  }
  EXPECT_EQ(dropped, 1000);
  EXPECT_EQ(MeasureDepth(model, model.far_limit_m + 0.5, 1.0, false, 7), 0);
  int edge_drops = 0;
  for (std::uint64_t key = 0; key < 1000; ++key) {
    if (MeasureDepth(model, 2.0, 1.0, true, key) == 0) ++edge_drops;
  }
  EXPECT_NEAR(edge_drops / 1000.0, model.edge_dropout_probability, 0.06);
}

}  // namespace
}  // namespace dynamap::robotio::sim
