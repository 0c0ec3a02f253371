// Joint rig calibration (thesis 8.4–8.5, extended): a closed-form planar hand-eye start,
// then one robust Ceres problem over every Kinect's 6-DoF mount and time offset and the two
// wheel scale factors, with per-parameter standard deviations and observability verdicts.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/calibration/CaptureData.hpp"
#include "dynamap/calibration/FloorPlane.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::calibration {

struct SolverConfig {
  // m, prior noise of one ICP pair's motion in its best-determined direction (rotations
  // count as the motion of points at the pair's lever, MotionPair::information).
  double translation_sigma_m = 0.0015;
  double floor_normal_sigma_rad = 0.002; // rad, noise of the combined floor normal.
  double floor_distance_sigma_m = 0.003; // m, noise of the combined floor distance.
  double wheel_heading_sigma_rad = 0.005;  // rad, wheel vs gyro heading over one stretch.
  double wheel_heading_stretch_s = 1.0;    // s, length of those stretches.
  double huber_width = 3.0;              // Whitened residual where the robust loss bends.
  // After a first solve, ICP pairs whose misfit exceeds this many times the median are
  // left out and the problem is solved again (0: keep every pair).
  double outlier_factor = 4.0;
  int max_iterations = 200;              // Levenberg-Marquardt iterations at most.
  double max_latency_s = 0.5;            // s, time offsets are searched in [-max, max].
  // Observability rules from the captured motion (per Kinect, over its accepted pairs).
  double min_turn_deg = 90.0;        // deg of turning below which x/y are not observable.
  double min_translation_m = 1.0;    // m of driving below which yaw and scales are weak.
  // A free parameter whose standard deviation exceeds its limit is reported as weak; the
  // limits are a third of the accuracy the rig needs (0.3°, 1 cm, 5 ms, 0.5 %).
  double max_angle_std_rad = 0.1 * M_PI / 180.0;  // rad.
  double max_translation_std_m = 0.0033;          // m.
  double max_latency_std_s = 0.0017;              // s.
  double max_scale_std = 0.0017;                  // 1 (relative).
};

enum class Observability { kCalibrated, kWeak, kNotObservable };
[[nodiscard]] const char* ObservabilityName(Observability o);

struct ParameterEstimate {
  std::string name;        // e.g. "kinect0.roll", "wheel_scale_left".
  std::string unit;        // "rad", "m", "s" or "1".
  double guess = 0.0;      // Value from the rig guess (nominal 1 for scales).
  double initial = 0.0;    // Closed-form start value.
  double estimate = 0.0;   // Refined value (equal to `initial` when held fixed).
  double std_dev = 0.0;    // From the Ceres covariance scaled by the residual variance.
  Observability status = Observability::kNotObservable;
  std::string reason;      // Why the status is not kCalibrated.
  // The value only when it may be used as calibrated.
  [[nodiscard]] std::optional<double> Calibrated() const {
    return status == Observability::kCalibrated ? std::optional<double>(estimate) : std::nullopt;
  }
};

// Motion that a Kinect's accepted pairs cover (base motion with nominal odometry).
struct MotionCoverage {
  double turned_deg = 0.0;       // deg, sum of |heading change| over pairs.
  double translated_m = 0.0;     // m, sum of |base displacement| over pairs.
  int pairs = 0;                 // Accepted ICP pairs.
};

// Per-pair and per-floor misfit, before and after refinement (for residual plots).
struct PairResidual {
  int kinect = 0;
  CaptureStep step = CaptureStep::kTurn;
  double t_s = 0.0;               // s since the first odometry reading.
  double rotation_deg = 0.0;      // deg, |rotation error| of predicted vs ICP motion.
  double translation_m = 0.0;     // m, |translation error|.
  bool left_out = false;          // Left out of the solution as an outlier.
};

struct KinectEstimate {
  std::string id;
  // Order: roll, pitch, yaw (rad, body frame in base), x, y, z (m, base), latency (s).
  std::vector<ParameterEstimate> parameters;
  FloorPose floor;               // Combined floor-plane fit (frames == 0 when none).
  MotionCoverage coverage;
};

struct SolverResult {
  bool converged = false;                 // Ceres reached a usable solution.
  std::string message;                    // Ceres' summary line or the reason it failed.
  std::vector<KinectEstimate> kinects;    // Rig order.
  ParameterEstimate scale_left;           // True wheel distance = scale × reported.
  ParameterEstimate scale_right;
  double residual_sigma_scale = 1.0;      // sqrt(reduced chi-square); std devs are scaled
                                          // by it when it exceeds 1.
  int outlier_pairs = 0;                  // ICP pairs left out (SolverConfig::outlier_factor).
  std::vector<PairResidual> initial_residuals;  // With the closed-form start.
  std::vector<PairResidual> final_residuals;    // After refinement.
  // Cross-check of the two Kinects: base motion implied by each over the same interval.
  int cross_check_pairs = 0;
  double cross_check_rotation_rms_deg = 0.0;
  double cross_check_translation_rms_m = 0.0;
  std::vector<std::string> warnings;      // Operator-readable observability notes.

  [[nodiscard]] bool AllCalibrated() const;
  // The guess rig with every estimate filled in (also the uncalibrated ones: check
  // AllCalibrated() or each parameter's status before trusting it).
  [[nodiscard]] robotio::Rig ToRig(const robotio::Rig& guess) const;
};

// Parameter index within KinectEstimate::parameters.
enum KinectParameter { kRoll = 0, kPitch, kYaw, kX, kY, kZ, kLatency, kKinectParameterCount };

[[nodiscard]] SolverResult SolveRig(const CaptureData& capture, const SolverConfig& config);

}  // namespace dynamap::calibration
