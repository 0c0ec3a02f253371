#include "dynamap/calibration/RigSolver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "SyntheticCapture.hpp"

namespace dynamap::calibration {
namespace {

constexpr double kDeg = M_PI / 180.0;

void ExpectRecovered(const SolverResult& result, const robotio::Rig& truth,
                     const test::SyntheticOptions& options) {
  ASSERT_TRUE(result.converged) << result.message;
  for (std::size_t k = 0; k < truth.kinects.size(); ++k) {
    const auto& p = result.kinects[k].parameters;
    const Eigen::Vector3d rpy = robotio::MountRollPitchYaw(truth.kinects[k].T_base_kinect);
    const Eigen::Vector3d t = truth.kinects[k].T_base_kinect.translation();
    for (int i = 0; i < 3; ++i) {
      SCOPED_TRACE(p[i].name);
      EXPECT_EQ(p[i].status, Observability::kCalibrated) << p[i].reason;
      EXPECT_NEAR(std::remainder(p[i].estimate - rpy[i], 2 * M_PI) / kDeg, 0.0, 0.3);
      EXPECT_EQ(p[3 + i].status, Observability::kCalibrated) << p[3 + i].reason;
      EXPECT_NEAR(p[3 + i].estimate, t[i], 0.01) << p[3 + i].name;
    }
    EXPECT_EQ(p[kLatency].status, Observability::kCalibrated) << p[kLatency].reason;
    EXPECT_NEAR(p[kLatency].estimate, truth.kinects[k].latency_s, 0.005);
  }
  EXPECT_NEAR(result.scale_left.estimate / options.scale_left, 1.0, 0.005);
  EXPECT_NEAR(result.scale_right.estimate / options.scale_right, 1.0, 0.005);
  EXPECT_EQ(result.scale_left.status, Observability::kCalibrated) << result.scale_left.reason;
  EXPECT_TRUE(result.AllCalibrated());
}

// The full guided sequence from the true rig, the guess off by up to 10° and 10 cm.
struct GuidedCapture {
  robotio::Rig truth = test::TrueRig();
  test::SyntheticOptions options;
  CaptureData capture;
};

GuidedCapture Guided(unsigned seed) {
  GuidedCapture guided;
  const robotio::Rig guess = test::PerturbedRig(guided.truth, 10.0 * kDeg, 0.10, 0.0, seed);
  guided.options.segments = test::GuidedSegments();
  guided.options.seed = seed;
  guided.capture = test::Synthesize(guided.truth, guess, guided.options);
  return guided;
}

class SolverRecovers : public ::testing::TestWithParam<unsigned> {};

TEST_P(SolverRecovers, PerturbedRigFromGuidedMotion) {
  const GuidedCapture guided = Guided(GetParam());
  const SolverResult result = SolveRig(guided.capture, SolverConfig{});
  ExpectRecovered(result, guided.truth, guided.options);
  // Both Kinects see the same base motion once calibrated.
  EXPECT_GT(result.cross_check_pairs, 10);
  EXPECT_LT(result.cross_check_rotation_rms_deg, 0.2);
  EXPECT_LT(result.cross_check_translation_rms_m, 0.01);
  // Refinement reduces the misfit.
  ASSERT_EQ(result.initial_residuals.size(), result.final_residuals.size());
  double before = 0.0, after = 0.0;
  for (std::size_t i = 0; i < result.final_residuals.size(); ++i) {
    before += result.initial_residuals[i].translation_m;
    after += result.final_residuals[i].translation_m;
  }
  EXPECT_LT(after, before);
}

INSTANTIATE_TEST_SUITE_P(Seeds, SolverRecovers, ::testing::Values(1u, 2u, 3u));

TEST(RigSolver, WithoutTurningXYAreNotObservableAndNotReported) {
  const robotio::Rig truth = test::TrueRig();
  const robotio::Rig guess = test::PerturbedRig(truth, 5.0 * kDeg, 0.05, 0.0, 7);
  test::SyntheticOptions options;
  options.segments = {{0.0, 0.0, 1.0, CaptureStep::kFloor},
                      {0.35, 0.0, 6.0, CaptureStep::kStraight},
                      {-0.35, 0.0, 6.0, CaptureStep::kStraight}};
  const SolverResult result = SolveRig(test::Synthesize(truth, guess, options), SolverConfig{});
  ASSERT_TRUE(result.converged) << result.message;
  for (const KinectEstimate& k : result.kinects) {
    for (int i : {kX, kY}) {
      EXPECT_EQ(k.parameters[i].status, Observability::kNotObservable);
      EXPECT_FALSE(k.parameters[i].Calibrated().has_value());
      EXPECT_NE(k.parameters[i].reason.find("not observable"), std::string::npos);
    }
    // The floor still gives height, roll and pitch.
    EXPECT_TRUE(k.parameters[kZ].Calibrated().has_value()) << k.parameters[kZ].reason;
  }
  EXPECT_FALSE(result.AllCalibrated());
}

TEST(RigSolver, WithoutDrivingYawIsNotCalibrated) {
  const robotio::Rig truth = test::TrueRig();
  const robotio::Rig guess = test::PerturbedRig(truth, 5.0 * kDeg, 0.05, 0.0, 8);
  test::SyntheticOptions options;
  options.segments = {{0.0, 0.0, 1.0, CaptureStep::kFloor},
                      {0.0, 0.6, 6.0, CaptureStep::kTurn},
                      {0.0, -0.6, 6.0, CaptureStep::kTurn}};
  const SolverResult result = SolveRig(test::Synthesize(truth, guess, options), SolverConfig{});
  for (const KinectEstimate& k : result.kinects) {
    EXPECT_FALSE(k.parameters[kYaw].Calibrated().has_value());
    EXPECT_FALSE(k.parameters[kX].Calibrated().has_value());
  }
  EXPECT_FALSE(result.scale_left.Calibrated().has_value());
}

// ICP that locked onto the wrong structure: one pair 0.5 m off. The first solve finds it
// far outside the others' misfit; it is left out and the rig is recovered as without it.
TEST(RigSolver, AGrossIcpFailureIsLeftOut) {
  GuidedCapture guided = Guided(4);
  std::vector<MotionPair>& motions = guided.capture.kinects[0].motions;
  ASSERT_GT(motions.size(), 20u);
  motions[motions.size() / 3].T_from_to.translation() += Eigen::Vector3d(0.5, 0.0, 0.2);
  const SolverResult result = SolveRig(guided.capture, SolverConfig{});
  EXPECT_GE(result.outlier_pairs, 1);
  EXPECT_LT(result.outlier_pairs, 5);
  // The corrupted pair is among those left out (marked for the residual plots).
  int marked = 0;
  bool corrupted_marked = false;
  for (std::size_t i = 0; i < result.final_residuals.size(); ++i) {
    marked += result.final_residuals[i].left_out ? 1 : 0;
    if (result.final_residuals[i].kinect == 0 &&
        std::abs(result.final_residuals[i].translation_m - 0.54) < 0.05) {
      corrupted_marked = result.final_residuals[i].left_out;
    }
  }
  EXPECT_EQ(marked, result.outlier_pairs);
  EXPECT_TRUE(corrupted_marked);
  ExpectRecovered(result, guided.truth, guided.options);
}

// In a corridor ICP cannot tell how far the sensor slid along it: such pairs carry large
// errors in that one direction, and their information says so. The solver must give that
// direction no weight; with uniform weights the same errors pull x/y off.
TEST(RigSolver, ErrorsAlongADirectionTheSceneCannotPinAreIgnored) {
  const GuidedCapture guided = Guided(6);
  const robotio::Rig& truth = guided.truth;
  CaptureData weighted = guided.capture;
  CaptureData uniform = weighted;
  for (std::size_t k = 0; k < weighted.kinects.size(); ++k) {
    for (std::size_t i = 0; i < weighted.kinects[k].motions.size(); i += 2) {
      // Slid 4 cm along optical x (sideways), a direction this pair's scene does not pin.
      for (CaptureData* capture : {&weighted, &uniform}) {
        capture->kinects[k].motions[i].T_from_to.translation().x() += 0.04;
      }
      Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Identity();
      information(3, 3) = 1e-4;
      weighted.kinects[k].motions[i].information = information;
    }
  }
  const SolverResult good = SolveRig(weighted, SolverConfig{});
  ASSERT_TRUE(good.converged);
  const SolverResult biased = SolveRig(uniform, SolverConfig{});
  ASSERT_TRUE(biased.converged);
  double good_error = 0.0, biased_error = 0.0;
  for (std::size_t k = 0; k < truth.kinects.size(); ++k) {
    const Eigen::Vector3d t = truth.kinects[k].T_base_kinect.translation();
    for (int i : {kX, kY}) {
      good_error = std::max(good_error, std::abs(good.kinects[k].parameters[i].estimate - t[i - kX]));
      biased_error =
          std::max(biased_error, std::abs(biased.kinects[k].parameters[i].estimate - t[i - kX]));
    }
  }
  std::printf("max x/y error: information-weighted %.4f m, uniform %.4f m\n", good_error,
              biased_error);
  EXPECT_LT(good_error, 0.004);
  EXPECT_LT(good_error, 0.5 * biased_error);
}

TEST(RigSolver, ToRigCarriesEstimates) {
  const robotio::Rig truth = test::TrueRig();
  const robotio::Rig guess = test::PerturbedRig(truth, 3.0 * kDeg, 0.03, 0.0, 9);
  test::SyntheticOptions options;
  options.segments = test::GuidedSegments();
  const SolverResult result = SolveRig(test::Synthesize(truth, guess, options), SolverConfig{});
  const robotio::Rig rig = result.ToRig(guess);
  ASSERT_EQ(rig.kinects.size(), 2u);
  EXPECT_TRUE(rig.kinects[0].T_base_kinect.isApprox(truth.kinects[0].T_base_kinect, 0.01));
  EXPECT_NEAR(rig.kinects[1].latency_s, 0.1, 0.005);
}

}  // namespace
}  // namespace dynamap::calibration
