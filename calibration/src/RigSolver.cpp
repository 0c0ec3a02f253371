#include "dynamap/calibration/RigSolver.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>

#include "RigResiduals.hpp"
#include "dynamap/calibration/BaseTrack.hpp"
#include "dynamap/calibration/HandEye.hpp"

namespace dynamap::calibration {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr const char* kNames[kKinectParameterCount] = {"roll", "pitch", "yaw", "x",
                                                      "y",    "z",     "latency"};
constexpr const char* kUnits[kKinectParameterCount] = {"rad", "rad", "rad", "m",
                                                      "m",   "m",   "s"};

// Solver-side state of one Kinect: parameter blocks and the observability decisions.
struct KinectState {
  double pose[6] = {0, 0, 0, 0, 0, 0};  // roll, pitch, yaw, x, y, z.
  double latency = 0.0;
  bool fixed[kKinectParameterCount] = {false, false, false, false, false, false, false};
  std::string reason[kKinectParameterCount];
  bool has_residuals = false;
};

std::string Format(const char* fmt, double a, double b) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), fmt, a, b);
  return buffer;
}

Eigen::Isometry3d BaseMotion(const BaseTrack& track, double t0_s, double t1_s, double scale_l,
                             double scale_r) {
  return track.At(t0_s, scale_l, scale_r).Between(track.At(t1_s, scale_l, scale_r)).ToIsometry();
}

Eigen::Isometry3d PoseOf(const KinectState& s) {
  return robotio::MountPose({s.pose[3], s.pose[4], s.pose[5]}, {s.pose[0], s.pose[1], s.pose[2]});
}

// Rotation (deg) and translation (m) error of every pair at the current parameters.
std::vector<PairResidual> PairResiduals(const CaptureData& capture, const BaseTrack& track,
                                        const internal::TrackInterpolator& interpolator,
                                        const std::vector<KinectState>& states,
                                        const double* scales) {
  std::vector<PairResidual> out;
  for (std::size_t k = 0; k < states.size(); ++k) {
    for (const MotionPair& pair : capture.kinects[k].motions) {
      const internal::HandEyeResidual residual(
          &interpolator, track.rate_hz(), track.Seconds(pair.from_received_ns),
          track.Seconds(pair.to_received_ns), pair.T_from_to,
          internal::HandEyeResidual::Matrix6::Identity(), 1.0, 1.0);
      double r[6];
      residual(states[k].pose, &states[k].latency, scales, r);
      out.push_back({static_cast<int>(k), pair.step, track.Seconds(pair.from_received_ns),
                     Eigen::Vector3d(r[0], r[1], r[2]).norm() / kDeg,
                     Eigen::Vector3d(r[3], r[4], r[5]).norm()});
    }
  }
  return out;
}

// Decides from the captured motion what each Kinect's data can determine, and computes
// the closed-form start (thesis 8.4–8.5) for what it can.
KinectState Initialise(const KinectCapture& kinect, const BaseTrack& track,
                       const SolverConfig& config, KinectEstimate* estimate) {
  KinectState s;
  const Eigen::Vector3d rpy = robotio::MountRollPitchYaw(kinect.guess.T_base_kinect);
  const Eigen::Vector3d t = kinect.guess.T_base_kinect.translation();
  s.pose[0] = rpy.x(), s.pose[1] = rpy.y(), s.pose[2] = rpy.z();
  s.pose[3] = t.x(), s.pose[4] = t.y(), s.pose[5] = t.z();
  s.latency = kinect.guess.latency_s;

  estimate->floor = CombineFloorFits(kinect.floor);
  const bool has_floor = estimate->floor.frames > 0;
  if (has_floor) {
    s.pose[0] = estimate->floor.roll_rad;
    s.pose[1] = estimate->floor.pitch_rad;
    s.pose[5] = estimate->floor.height_m;
  }

  std::vector<MotionCorrespondence> correspondences;
  MotionCoverage& coverage = estimate->coverage;
  for (const MotionPair& pair : kinect.motions) {
    const Eigen::Isometry3d B =
        BaseMotion(track, track.Seconds(pair.from_received_ns) - s.latency,
                   track.Seconds(pair.to_received_ns) - s.latency, 1.0, 1.0);
    correspondences.push_back({pair.T_from_to, B});
    coverage.turned_deg += std::abs(std::atan2(B.linear()(1, 0), B.linear()(0, 0))) / kDeg;
    coverage.translated_m += B.translation().norm();
    ++coverage.pairs;
  }
  const bool turned = coverage.turned_deg >= config.min_turn_deg;
  const bool drove = coverage.translated_m >= config.min_translation_m;
  // Some driving (a tenth of the target) keeps yaw free, though still reported weak.
  const bool some_driving = coverage.translated_m >= 0.1 * config.min_translation_m;

  if (!turned) {
    const std::string why = Format(
        "not observable: the capture turned %.0f deg, x/y need at least %.0f deg of turning "
        "in place",
        coverage.turned_deg, config.min_turn_deg);
    s.fixed[kX] = s.fixed[kY] = true;
    s.reason[kX] = s.reason[kY] = why;
  }
  if (!drove) {
    s.reason[kYaw] = Format(
        "weak: the capture drove %.2f m, yaw needs at least %.1f m of straight or arc driving",
        coverage.translated_m, config.min_translation_m);
    if (!some_driving) {
      s.fixed[kYaw] = true;
      s.reason[kYaw] = "not observable" + s.reason[kYaw].substr(4) + " (held at the guess)";
    }
    if (turned) {
      // Pure turns fix x/y only relative to the (guessed) yaw.
      s.reason[kX] = s.reason[kY] = "weak: depends on yaw, which the capture does not determine";
    }
  }
  if (!has_floor) {
    s.fixed[kZ] = true;
    s.reason[kZ] = "not observable: no floor-plane fit (planar motion does not show height)";
    if (!turned) {
      s.fixed[kRoll] = s.fixed[kPitch] = true;
      s.reason[kRoll] = s.reason[kPitch] = "not observable: no floor-plane fit and no turning";
    }
  }
  if (kinect.motions.empty()) {
    s.fixed[kLatency] = s.fixed[kYaw] = true;
    s.reason[kLatency] = "not observable: no motion captured";
    if (s.reason[kYaw].empty()) s.reason[kYaw] = s.reason[kLatency];
  }

  PlanarHandEye guess{true, s.pose[2], s.pose[3], s.pose[4]};
  const PlanarHandEye init = SolvePlanarHandEye(correspondences, s.pose[0], s.pose[1], guess,
                                                !s.fixed[kYaw], !s.fixed[kX]);
  if (init.ok) {
    s.pose[2] = init.yaw_rad;
    s.pose[3] = init.x_m;
    s.pose[4] = init.y_m;
  }

  estimate->id = kinect.guess.id;
  const double guesses[kKinectParameterCount] = {rpy.x(), rpy.y(), rpy.z(),
                                                 t.x(),   t.y(),   t.z(),
                                                 kinect.guess.latency_s};
  for (int i = 0; i < kKinectParameterCount; ++i) {
    ParameterEstimate p;
    p.name = kinect.guess.id + "." + kNames[i];
    p.unit = kUnits[i];
    p.guess = guesses[i];
    p.initial = i < 6 ? s.pose[i] : s.latency;
    estimate->parameters.push_back(p);
  }
  s.has_residuals = has_floor || !kinect.motions.empty();
  return s;
}

void AddPoseBlock(ceres::Problem* problem, KinectState* s) {
  std::vector<int> fixed;
  for (int i = 0; i < 6; ++i) {
    if (s->fixed[i]) fixed.push_back(i);
  }
  if (fixed.size() == 6) {
    problem->SetParameterBlockConstant(s->pose);
  } else if (!fixed.empty()) {
    problem->SetManifold(s->pose, new ceres::SubsetManifold(6, fixed));
  }
}

// Standard deviations of the free parameters, or false when the problem is rank deficient.
bool ComputeStdDevs(ceres::Problem* problem, std::vector<KinectState>* states, double* scales,
                    bool scales_fixed, double sigma_scale, SolverResult* result) {
  ceres::Covariance::Options options;
  options.algorithm_type = ceres::DENSE_SVD;
  ceres::Covariance covariance(options);
  std::vector<std::pair<const double*, const double*>> blocks;
  for (KinectState& s : *states) {
    if (!s.has_residuals) continue;
    if (!problem->IsParameterBlockConstant(s.pose)) blocks.emplace_back(s.pose, s.pose);
    if (!s.fixed[kLatency]) blocks.emplace_back(&s.latency, &s.latency);
  }
  if (!scales_fixed) blocks.emplace_back(scales, scales);
  if (!covariance.Compute(blocks, problem)) return false;
  for (std::size_t k = 0; k < states->size(); ++k) {
    KinectState& s = (*states)[k];
    if (!s.has_residuals) continue;
    auto& params = result->kinects[k].parameters;
    if (!problem->IsParameterBlockConstant(s.pose)) {
      double cov[36];
      covariance.GetCovarianceBlock(s.pose, s.pose, cov);
      for (int i = 0; i < 6; ++i) params[i].std_dev = std::sqrt(cov[i * 7]) * sigma_scale;
    }
    if (!s.fixed[kLatency]) {
      double cov = 0.0;
      covariance.GetCovarianceBlock(&s.latency, &s.latency, &cov);
      params[kLatency].std_dev = std::sqrt(cov) * sigma_scale;
    }
  }
  if (!scales_fixed) {
    double cov[4];
    covariance.GetCovarianceBlock(scales, scales, cov);
    result->scale_left.std_dev = std::sqrt(cov[0]) * sigma_scale;
    result->scale_right.std_dev = std::sqrt(cov[3]) * sigma_scale;
  }
  return true;
}

// Removes the hand-eye blocks whose weighted misfit exceeds `factor` × the median misfit
// (ICP that slid along a featureless direction or locked onto the wrong structure), so they
// neither pull the solution nor widen the covariance. Returns which were removed.
std::vector<bool> RemoveOutlierPairs(ceres::Problem* problem,
                                     const std::vector<ceres::ResidualBlockId>& blocks,
                                     double factor) {
  std::vector<bool> removed(blocks.size(), false);
  if (blocks.size() < 3 || !(factor > 0.0)) return removed;
  std::vector<double> misfit;
  misfit.reserve(blocks.size());
  for (const ceres::ResidualBlockId id : blocks) {
    double cost = 0.0;
    double residual[6];
    problem->EvaluateResidualBlock(id, false, &cost, residual, nullptr);
    misfit.push_back(Eigen::Map<const Eigen::Matrix<double, 6, 1>>(residual).norm());
  }
  std::vector<double> sorted = misfit;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double limit = factor * sorted[sorted.size() / 2];
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    if (misfit[i] > limit) {
      problem->RemoveResidualBlock(blocks[i]);
      removed[i] = true;
    }
  }
  return removed;
}

// Calibrated when free, determined (covariance) and within its std-dev limit.
void Judge(ParameterEstimate* p, bool fixed, const std::string& rule_reason, bool have_std,
           double limit) {
  if (fixed) {
    p->status = Observability::kNotObservable;
    p->reason = rule_reason.empty() ? "not observable" : rule_reason;
  } else if (!rule_reason.empty()) {
    p->status = Observability::kWeak;
    p->reason = rule_reason;
  } else if (!have_std) {
    p->status = Observability::kNotObservable;
    p->reason = "not observable: the captured motion leaves the problem rank deficient";
  } else if (!(p->std_dev <= limit)) {
    p->status = Observability::kWeak;
    p->reason = Format("weak: standard deviation %.3g exceeds the limit %.3g", p->std_dev, limit);
  } else {
    p->status = Observability::kCalibrated;
    p->reason.clear();
  }
}

// Both Kinects must imply the same base motion. Their keyframes are up to a frame period
// apart, so the other Kinect's interval is bridged to this one's with the (short, hence
// accurate) odometry in between.
void CrossCheck(const CaptureData& capture, const BaseTrack& track,
                const std::vector<KinectState>& states, const double* scales,
                SolverResult* result) {
  if (states.size() < 2 || track.empty()) return;
  constexpr double kMaxOffsetS = 0.15;  // s, up to one frame period at 6.7 Hz and above.
  auto odometry = [&](double t0, double t1) {
    return BaseMotion(track, t0, t1, scales[0], scales[1]);
  };
  double rot_sq = 0.0, trans_sq = 0.0;
  int n = 0;
  const Eigen::Isometry3d X0 = PoseOf(states[0]);
  for (std::size_t k = 1; k < states.size(); ++k) {
    const Eigen::Isometry3d Xk = PoseOf(states[k]);
    for (const MotionPair& a : capture.kinects[0].motions) {
      const double a0 = track.Seconds(a.from_received_ns) - states[0].latency;
      const double a1 = track.Seconds(a.to_received_ns) - states[0].latency;
      for (const MotionPair& b : capture.kinects[k].motions) {
        const double b0 = track.Seconds(b.from_received_ns) - states[k].latency;
        const double b1 = track.Seconds(b.to_received_ns) - states[k].latency;
        if (std::abs(a0 - b0) > kMaxOffsetS || std::abs(a1 - b1) > kMaxOffsetS) continue;
        const Eigen::Isometry3d from_a = X0 * a.T_from_to * X0.inverse();
        const Eigen::Isometry3d from_b =
            odometry(a0, b0) * (Xk * b.T_from_to * Xk.inverse()) * odometry(b1, a1);
        const Eigen::Isometry3d diff = from_a.inverse() * from_b;
        rot_sq += std::pow(Eigen::AngleAxisd(diff.linear()).angle() / kDeg, 2);
        trans_sq += diff.translation().squaredNorm();
        ++n;
      }
    }
  }
  result->cross_check_pairs = n;
  if (n > 0) {
    result->cross_check_rotation_rms_deg = std::sqrt(rot_sq / n);
    result->cross_check_translation_rms_m = std::sqrt(trans_sq / n);
  }
}

}  // namespace

const char* ObservabilityName(Observability o) {
  switch (o) {
    case Observability::kCalibrated: return "calibrated";
    case Observability::kWeak: return "weak";
    case Observability::kNotObservable: return "not_observable";
  }
  return "unknown";
}

bool SolverResult::AllCalibrated() const {
  if (!converged) return false;
  for (const KinectEstimate& k : kinects) {
    for (const ParameterEstimate& p : k.parameters) {
      if (p.status != Observability::kCalibrated) return false;
    }
  }
  return scale_left.status == Observability::kCalibrated &&
         scale_right.status == Observability::kCalibrated;
}

robotio::Rig SolverResult::ToRig(const robotio::Rig& guess) const {
  robotio::Rig rig = guess;
  for (std::size_t k = 0; k < kinects.size() && k < rig.kinects.size(); ++k) {
    const auto& p = kinects[k].parameters;
    rig.kinects[k].T_base_kinect = robotio::MountPose(
        {p[kX].estimate, p[kY].estimate, p[kZ].estimate},
        {p[kRoll].estimate, p[kPitch].estimate, p[kYaw].estimate});
    rig.kinects[k].latency_s = p[kLatency].estimate;
  }
  return rig;
}

SolverResult SolveRig(const CaptureData& capture, const SolverConfig& config) {
  SolverResult result;
  const BaseTrack track =
      BaseTrack::Build(capture.odometry, capture.imu, {200.0, capture.gyro_bias_rad_s});
  const internal::TrackGrid grid(track.samples().data(), 0, std::max(track.size(), 1));
  const internal::TrackInterpolator interpolator(grid);

  std::vector<KinectState> states;
  states.reserve(capture.kinects.size());
  result.kinects.resize(capture.kinects.size());
  for (std::size_t k = 0; k < capture.kinects.size(); ++k) {
    states.push_back(Initialise(capture.kinects[k], track, config, &result.kinects[k]));
  }
  double translated = 0.0;
  for (const KinectEstimate& k : result.kinects) translated = std::max(translated, k.coverage.translated_m);
  double scales[2] = {1.0, 1.0};
  const bool scales_fixed = translated < config.min_translation_m || track.empty();
  const std::string scale_reason =
      scales_fixed ? Format("not observable: the capture drove %.2f m, wheel scales need at "
                            "least %.1f m",
                            translated, config.min_translation_m)
                   : "";
  result.scale_left = {"wheel_scale_left", "1", 1.0, 1.0, 1.0, 0.0,
                       Observability::kNotObservable, ""};
  result.scale_right = result.scale_left;
  result.scale_right.name = "wheel_scale_right";
  if (!track.empty()) {
    result.initial_residuals = PairResiduals(capture, track, interpolator, states, scales);
  }

  ceres::Problem problem;
  int residual_count = 0;
  std::vector<ceres::ResidualBlockId> hand_eye_blocks;
  for (std::size_t k = 0; k < states.size(); ++k) {
    KinectState& s = states[k];
    const KinectCapture& kinect = capture.kinects[k];
    const FloorPose& floor = result.kinects[k].floor;
    if (floor.frames > 0) {
      // One observation for the averaged plane: per-frame fits share their systematic error.
      PlaneFit plane;
      plane.normal = Eigen::Vector3d::Zero();
      for (const PlaneFit& f : kinect.floor) {
        if (f.ok) plane.normal += f.normal, plane.distance_m += f.distance_m;
      }
      plane.normal.normalize();
      plane.distance_m /= floor.frames;
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<internal::FloorResidual, 4, 6>(new internal::FloorResidual(
              plane.normal, plane.distance_m, config.floor_normal_sigma_rad,
              config.floor_distance_sigma_m)),
          new ceres::HuberLoss(config.huber_width), s.pose);
      residual_count += 4;
    }
    if (!track.empty()) {
      for (const MotionPair& pair : kinect.motions) {
        hand_eye_blocks.push_back(problem.AddResidualBlock(
            new ceres::AutoDiffCostFunction<internal::HandEyeResidual, 6, 6, 1, 2>(
                new internal::HandEyeResidual(&interpolator, track.rate_hz(),
                                              track.Seconds(pair.from_received_ns),
                                              track.Seconds(pair.to_received_ns), pair.T_from_to,
                                              pair.information, pair.lever_m,
                                              config.translation_sigma_m)),
            new ceres::HuberLoss(config.huber_width), s.pose, &s.latency, scales));
        residual_count += 6;
      }
    }
    if (!s.has_residuals) continue;
    AddPoseBlock(&problem, &s);
    if (problem.HasParameterBlock(&s.latency)) {
      if (s.fixed[kLatency]) {
        problem.SetParameterBlockConstant(&s.latency);
      } else {
        problem.SetParameterLowerBound(&s.latency, 0, -config.max_latency_s);
        problem.SetParameterUpperBound(&s.latency, 0, config.max_latency_s);
      }
    }
  }
  if (!track.empty() && !scales_fixed) {
    // Wheel heading vs gyro over fixed stretches while the base turns.
    const int stride = std::max(1, static_cast<int>(config.wheel_heading_stretch_s * track.rate_hz()));
    for (int i = 0; i + stride < track.size(); i += stride) {
      const double dl = track.left_m()[i + stride] - track.left_m()[i];
      const double dr = track.right_m()[i + stride] - track.right_m()[i];
      const double dtheta = track.samples()[(i + stride) * 5] - track.samples()[i * 5];
      if (std::abs(dl) + std::abs(dr) < 1e-4) continue;
      problem.AddResidualBlock(
          new ceres::AutoDiffCostFunction<internal::WheelHeadingResidual, 1, 2>(
              new internal::WheelHeadingResidual(dl, dr, dtheta, capture.track_width_m,
                                                 config.wheel_heading_sigma_rad)),
          new ceres::HuberLoss(config.huber_width), scales);
      residual_count += 1;
    }
  }
  if (problem.HasParameterBlock(scales) && scales_fixed) problem.SetParameterBlockConstant(scales);
  if (residual_count == 0) {
    result.message = "nothing to solve: no floor-plane fit and no motion pair";
    return result;
  }

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = config.max_iterations;
  options.function_tolerance = 1e-10;
  options.parameter_tolerance = 1e-10;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  const std::vector<bool> left_out =
      RemoveOutlierPairs(&problem, hand_eye_blocks, config.outlier_factor);
  result.outlier_pairs = static_cast<int>(std::count(left_out.begin(), left_out.end(), true));
  if (result.outlier_pairs > 0) {
    residual_count -= 6 * result.outlier_pairs;
    ceres::Solve(options, &problem, &summary);
    result.warnings.push_back(
        std::to_string(result.outlier_pairs) +
        Format(" ICP pair(s) left out: misfit above %.0f× the median of %.0f pairs",
               config.outlier_factor, static_cast<double>(hand_eye_blocks.size())));
  }
  result.converged = summary.IsSolutionUsable();
  result.message = summary.BriefReport();

  int free_parameters = 0;
  for (const KinectState& s : states) {
    for (int i = 0; i < kKinectParameterCount; ++i) free_parameters += s.fixed[i] ? 0 : 1;
  }
  free_parameters += scales_fixed ? 0 : 2;
  const int dof = std::max(1, residual_count - free_parameters);
  result.residual_sigma_scale = std::sqrt(2.0 * summary.final_cost / dof);
  // Misfits above the priors widen the standard deviations; misfits below them do not
  // narrow them, since pairs sharing frames and wheel slip are not independent errors.
  const bool have_std = result.converged &&
                        ComputeStdDevs(&problem, &states, scales, scales_fixed,
                                       std::max(1.0, result.residual_sigma_scale), &result);

  const double limits[kKinectParameterCount] = {
      config.max_angle_std_rad,     config.max_angle_std_rad,     config.max_angle_std_rad,
      config.max_translation_std_m, config.max_translation_std_m, config.max_translation_std_m,
      config.max_latency_std_s};
  for (std::size_t k = 0; k < states.size(); ++k) {
    KinectState& s = states[k];
    auto& params = result.kinects[k].parameters;
    for (int i = 0; i < kKinectParameterCount; ++i) {
      params[i].estimate = i < 6 ? s.pose[i] : s.latency;
      Judge(&params[i], s.fixed[i] || !s.has_residuals, s.reason[i], have_std, limits[i]);
      if (!params[i].reason.empty()) {
        result.warnings.push_back(params[i].name + ": " + params[i].reason);
      }
    }
  }
  result.scale_left.estimate = scales[0];
  result.scale_right.estimate = scales[1];
  for (ParameterEstimate* p : {&result.scale_left, &result.scale_right}) {
    Judge(p, scales_fixed, scale_reason, have_std, config.max_scale_std);
    if (!p->reason.empty()) result.warnings.push_back(p->name + ": " + p->reason);
  }
  if (!track.empty()) {
    result.final_residuals = PairResiduals(capture, track, interpolator, states, scales);
    // Same pair order as the hand-eye blocks.
    for (std::size_t i = 0; i < left_out.size() && i < result.final_residuals.size(); ++i) {
      result.final_residuals[i].left_out = left_out[i];
      result.initial_residuals[i].left_out = left_out[i];
    }
  }
  CrossCheck(capture, track, states, scales, &result);
  return result;
}

}  // namespace dynamap::calibration
