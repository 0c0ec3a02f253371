#include "dynamap/calibration/CalibrationSession.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::calibration {
namespace {

constexpr double kDeg = M_PI / 180.0;

bool IsCapture(SessionStep step) { return step <= SessionStep::kArcs; }

// Points of every `stride`-th pixel within the mount's range, optical frame.
robotio::PointList SubsampledPoints(const robotio::DepthFrame& frame,
                                    const robotio::KinectMount& mount, int stride) {
  const robotio::Intrinsics& k = frame.intrinsics;
  robotio::PointList points;
  for (int v = 0; v < frame.height; v += stride) {
    for (int u = 0; u < frame.width; u += stride) {
      const double z = frame.At(u, v) * 0.001;
      if (z < mount.min_range_m || z > mount.max_range_m) continue;
      points.emplace_back(static_cast<float>((u - k.cx) / k.fx * z),
                          static_cast<float>((v - k.cy) / k.fy * z), static_cast<float>(z));
    }
  }
  return points;
}

template <typename... Args>
std::string Printf(const char* fmt, Args... args) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), fmt, args...);
  return buffer;
}

}  // namespace

const char* SessionStepName(SessionStep step) {
  switch (step) {
    case SessionStep::kFloor: return "floor";
    case SessionStep::kTurn: return "turn";
    case SessionStep::kStraight: return "straight";
    case SessionStep::kArcs: return "arcs";
    case SessionStep::kSolve: return "solve";
    case SessionStep::kReview: return "review";
    case SessionStep::kSave: return "save";
    case SessionStep::kDone: return "done";
  }
  return "unknown";
}

CalibrationSession::CalibrationSession(robotio::Rig guess, SessionConfig config)
    : guess_(std::move(guess)), config_(std::move(config)) {
  keyframes_.resize(guess_.kinects.size());
  next_keyframe_ns_.assign(guess_.kinects.size(), 0);
  for (StepTally& t : tallies_) {
    t.pairs.assign(guess_.kinects.size(), 0);
    t.rejected.assign(guess_.kinects.size(), 0);
  }
  for (const robotio::KinectMount& m : guess_.kinects) capture_.kinects.push_back({m, {}, {}});
  capture_.track_width_m = config_.track_width_m;
}

CalibrationSession::StepTally& CalibrationSession::Tally(SessionStep step) {
  return tallies_[std::min(static_cast<int>(step), 3)];
}
const CalibrationSession::StepTally& CalibrationSession::Tally(SessionStep step) const {
  return tallies_[std::min(static_cast<int>(step), 3)];
}

double CalibrationSession::gyro_bias_rad_s() const {
  return bias_count_ > 0 ? bias_sum_ / bias_count_ : 0.0;
}

void CalibrationSession::AddImu(const robotio::ImuReading& reading) {
  if (!capture_.imu.empty()) {
    const double dt = robotio::NanosToSeconds(reading.stamp_ns - capture_.imu.back().stamp_ns);
    heading_ += (capture_.imu.back().wz - gyro_bias_rad_s()) * dt;
  }
  // Counted towards the bias only once the next odometry reading confirms standing still.
  pending_bias_sum_ += reading.wz;
  ++pending_bias_count_;
  capture_.imu.push_back(reading);
}

void CalibrationSession::AddOdometry(const robotio::OdometryReading& reading) {
  if (capture_.odometry.empty()) {
    dead_reckoning_.push_back({reading.stamp_ns, robotio::Pose2D{}});
  } else {
    const robotio::OdometryReading& prev = capture_.odometry.back();
    const double ds = 0.5 * ((reading.left_m - prev.left_m) + (reading.right_m - prev.right_m));
    const double dtheta = heading_ - heading_at_odometry_;
    const double dt = std::max(1e-6, robotio::NanosToSeconds(reading.stamp_ns - prev.stamp_ns));
    const bool was_still = still_;
    still_ = std::abs(ds) / dt < config_.still_speed_mps &&
             std::abs(dtheta) / dt < config_.still_yaw_rate_radps;
    if (still_ && was_still) {
      bias_sum_ += pending_bias_sum_;
      bias_count_ += pending_bias_count_;
    }
    dead_reckoning_.push_back(
        {reading.stamp_ns, dead_reckoning_.back().second.Compose(
                               {ds * std::cos(0.5 * dtheta), ds * std::sin(0.5 * dtheta), dtheta})});
    if (IsCapture(step_) && !still_) {
      StepTally& t = Tally(step_);
      if (std::abs(ds) < 0.05 * std::abs(dtheta)) {
        (dtheta > 0 ? t.left_deg : t.right_deg) += std::abs(dtheta) / kDeg;
      } else if (std::abs(dtheta) < config_.straight_max_curvature * std::abs(ds)) {
        (ds > 0 ? t.forward_m : t.backward_m) += std::abs(ds);
      } else {
        (dtheta > 0 ? t.arc_left_m : t.arc_right_m) += std::abs(ds);
      }
    }
  }
  heading_at_odometry_ = heading_;
  pending_bias_sum_ = 0.0;
  pending_bias_count_ = 0;
  capture_.odometry.push_back(reading);
}

robotio::Pose2D CalibrationSession::DeadReckonedAt(std::int64_t stamp_ns) const {
  if (dead_reckoning_.empty()) return {};
  auto it = std::lower_bound(dead_reckoning_.begin(), dead_reckoning_.end(), stamp_ns,
                             [](const auto& e, std::int64_t t) { return e.first < t; });
  if (it == dead_reckoning_.begin()) return it->second;
  if (it == dead_reckoning_.end()) return dead_reckoning_.back().second;
  const auto& a = *std::prev(it);
  const double s = static_cast<double>(stamp_ns - a.first) / static_cast<double>(it->first - a.first);
  return robotio::Interpolate(a.second, it->second, s);
}

void CalibrationSession::AddDepth(const robotio::DepthFrame& frame) {
  if (frame.sensor_id < 0 || frame.sensor_id >= static_cast<int>(guess_.kinects.size()) ||
      !frame.Valid()) {
    return;
  }
  if (step_ == SessionStep::kFloor) {
    AddFloorFrame(frame);
  } else if (IsCapture(step_)) {
    AddMotionFrame(frame);
  }
}

void CalibrationSession::AddFloorFrame(const robotio::DepthFrame& frame) {
  if (!still_) return;  // A moving robot may rock; the floor step wants it at rest.
  const robotio::KinectMount& mount = guess_.kinects[frame.sensor_id];
  const PlaneFit fit =
      FitPlane(SubsampledPoints(frame, mount, config_.floor_pixel_stride), config_.plane,
               FloorNormalInKinect(mount.T_base_kinect));
  if (fit.ok && fit.inlier_share >= config_.min_floor_inlier_share) {
    capture_.kinects[frame.sensor_id].floor.push_back(fit);
    ++Tally(SessionStep::kFloor).pairs[frame.sensor_id];
  }
}

void CalibrationSession::AddMotionFrame(const robotio::DepthFrame& frame) {
  const int sensor = frame.sensor_id;
  if (frame.received_ns < next_keyframe_ns_[sensor]) return;
  const std::int64_t interval_ns = robotio::SecondsToNanos(config_.keyframe_interval_s);
  next_keyframe_ns_[sensor] = (frame.received_ns / interval_ns + 1) * interval_ns;
  const robotio::KinectMount& mount = guess_.kinects[sensor];
  Keyframe next{frame.received_ns, PrepareCloud(SubsampledPoints(frame, mount, 2), config_.icp)};
  std::vector<Keyframe>& history = keyframes_[sensor];
  if (!history.empty()) AddPair(sensor, history.back(), next);
  const auto long_back = static_cast<std::size_t>(std::max(2, config_.long_baseline_keyframes));
  if (history.size() >= long_back) AddPair(sensor, history[history.size() - long_back], next);
  history.push_back(std::move(next));
  if (history.size() > long_back) history.erase(history.begin());
}

void CalibrationSession::AddPair(int sensor, const Keyframe& from, const Keyframe& to) {
  const robotio::KinectMount& mount = guess_.kinects[sensor];
  const std::int64_t latency_ns = robotio::SecondsToNanos(mount.latency_s);
  const Eigen::Isometry3d B = DeadReckonedAt(from.received_ns - latency_ns)
                                  .Between(DeadReckonedAt(to.received_ns - latency_ns))
                                  .ToIsometry();
  const Eigen::Isometry3d& X = mount.T_base_kinect;
  const SensorMotionResult motion =
      EstimateSensorMotion(from.cloud, to.cloud, X.inverse() * B * X, config_.icp);
  StepTally& t = Tally(step_);
  if (!motion.accepted) {
    ++t.rejected[sensor];
    return;
  }
  MotionPair pair;
  // Tagged by the motion itself, so a recording without step marks plots the same way.
  const double dtheta = std::abs(robotio::Pose2D::FromIsometry(B).theta);
  const double ds = B.translation().norm();
  pair.step = ds < 0.1 * dtheta                              ? CaptureStep::kTurn
              : dtheta < config_.straight_max_curvature * ds ? CaptureStep::kStraight
                                                             : CaptureStep::kArcs;
  pair.from_received_ns = from.received_ns;
  pair.to_received_ns = to.received_ns;
  pair.T_from_to = motion.T_from_to;
  pair.rms_m = motion.rms_m;
  pair.structure = motion.structure;
  pair.information = motion.information;
  pair.lever_m = motion.lever_m;
  capture_.kinects[sensor].motions.push_back(pair);
  ++t.pairs[sensor];
}

SessionProgress CalibrationSession::Progress() const {
  SessionProgress p;
  p.step = step_;
  const std::size_t n = guess_.kinects.size();
  int min_fits = n > 0 ? config_.floor_frames : 0;
  for (std::size_t k = 0; k < n; ++k) {
    // Fits of the current floor step (a redo counts afresh; earlier fits are kept).
    p.floor_fits.push_back(Tally(SessionStep::kFloor).pairs[k]);
    min_fits = std::min(min_fits, p.floor_fits.back());
  }
  const StepTally& t = Tally(step_);
  p.step_pairs = t.pairs;
  p.rejected_pairs = t.rejected;
  int min_pairs = config_.min_pairs_per_step;
  for (int c : t.pairs) min_pairs = std::min(min_pairs, c);
  const double pair_share = static_cast<double>(min_pairs) / config_.min_pairs_per_step;
  p.turned_left_deg = t.left_deg;
  p.turned_right_deg = t.right_deg;
  p.forward_m = t.forward_m;
  p.backward_m = t.backward_m;
  p.arc_left_m = t.arc_left_m;
  p.arc_right_m = t.arc_right_m;
  switch (step_) {
    case SessionStep::kFloor:
      p.instruction = "Keep the robot still on a flat, open floor.";
      p.fraction = static_cast<double>(min_fits) / config_.floor_frames;
      p.detail = Printf("floor fits %d of %d per Kinect (gyro bias %.4f rad/s)", min_fits,
                        config_.floor_frames, gyro_bias_rad_s());
      break;
    case SessionStep::kTurn:
      p.instruction = "Turn in place slowly, both ways, facing walls and furniture.";
      p.fraction = std::min({t.left_deg / config_.turn_target_deg,
                             t.right_deg / config_.turn_target_deg, pair_share});
      p.detail = Printf("left %.0f deg, right %.0f deg of %.0f each; pairs %d",
                        t.left_deg, t.right_deg, config_.turn_target_deg, min_pairs);
      break;
    case SessionStep::kStraight:
      p.instruction = "Drive straight forward, then back, towards a structured scene.";
      p.fraction = std::min({t.forward_m / config_.straight_target_m,
                             t.backward_m / config_.straight_target_m, pair_share});
      p.detail = Printf("forward %.2f m, back %.2f m of %.2f each; pairs %d", t.forward_m,
                        t.backward_m, config_.straight_target_m, min_pairs);
      break;
    case SessionStep::kArcs:
      p.instruction = "Drive arcs to the left and to the right, speeding up and slowing down.";
      p.fraction = std::min({t.arc_left_m / config_.arc_target_m,
                             t.arc_right_m / config_.arc_target_m, pair_share});
      p.detail = Printf("left arcs %.2f m, right arcs %.2f m of %.2f each; pairs %d",
                        t.arc_left_m, t.arc_right_m, config_.arc_target_m, min_pairs);
      break;
    case SessionStep::kSolve:
      p.instruction = "Capture complete: stop the robot and solve.";
      p.fraction = 1.0;
      break;
    case SessionStep::kReview: {
      int calibrated = 0, total = 0;
      if (result_) {
        for (const KinectEstimate& k : result_->kinects) {
          for (const ParameterEstimate& e : k.parameters) {
            total += 1;
            calibrated += e.status == Observability::kCalibrated ? 1 : 0;
          }
        }
        for (const ParameterEstimate* e : {&result_->scale_left, &result_->scale_right}) {
          total += 1;
          calibrated += e->status == Observability::kCalibrated ? 1 : 0;
        }
      }
      p.redo = StepForUncalibrated();
      p.instruction =
          calibrated == total
              ? "Review the estimates and residual plots, then save."
              : p.redo ? std::string("Some parameters are not calibrated: redo the '") +
                             SessionStepName(*p.redo) +
                             "' step for more data, or save anyway only if you accept the "
                             "guess for them."
                       : "Some parameters are not calibrated: redo the step the warnings "
                         "name, or save anyway only if you accept the guess for them.";
      p.fraction = total > 0 ? static_cast<double>(calibrated) / total : 0.0;
      p.detail = Printf("%d of %d parameters calibrated", calibrated, total);
      break;
    }
    case SessionStep::kSave:
      p.instruction = "Save the rig file.";
      p.fraction = 1.0;
      break;
    case SessionStep::kDone:
      p.instruction = "Calibration saved.";
      p.fraction = 1.0;
      break;
  }
  p.complete = IsCapture(step_) ? p.fraction >= 1.0
                                : step_ == SessionStep::kSolve || step_ == SessionStep::kReview;
  p.fraction = std::clamp(p.fraction, 0.0, 1.0);
  return p;
}

robotio::Status CalibrationSession::Advance() {
  if (step_ == SessionStep::kSave || step_ == SessionStep::kDone) {
    return robotio::Error{std::string("calibration session: step '") + SessionStepName(step_) +
                          "' ends with Save(), not Advance()"};
  }
  if (IsCapture(step_)) {
    const SessionProgress p = Progress();
    if (p.fraction < 1.0) {
      return robotio::Error{std::string("calibration session: step '") +
                            SessionStepName(step_) + "' is incomplete (" + p.detail +
                            "); continue, or Skip() it"};
    }
  }
  if (step_ == SessionStep::kSolve) {
    Solve();
    return robotio::Ok{};
  }
  step_ = static_cast<SessionStep>(static_cast<int>(step_) + 1);
  return robotio::Ok{};
}

void CalibrationSession::Skip() {
  if (IsCapture(step_)) step_ = static_cast<SessionStep>(static_cast<int>(step_) + 1);
}

const SolverResult& CalibrationSession::Solve() {
  capture_.gyro_bias_rad_s = gyro_bias_rad_s();
  capture_.track_width_m = config_.track_width_m;
  result_ = SolveRig(capture_, config_.solver);
  step_ = SessionStep::kReview;
  return *result_;
}

void CalibrationSession::Redo(SessionStep capture_step) {
  if (!IsCapture(capture_step) || step_ == SessionStep::kDone) return;
  step_ = capture_step;
  for (auto& k : keyframes_) k.clear();  // No pair spans the pause.
  StepTally& t = Tally(step_);
  t = StepTally{};
  t.pairs.assign(guess_.kinects.size(), 0);
  t.rejected.assign(guess_.kinects.size(), 0);
}

std::optional<SessionStep> CalibrationSession::StepForUncalibrated() const {
  if (!result_) return std::nullopt;
  auto weak = [](const ParameterEstimate& p) { return p.status != Observability::kCalibrated; };
  for (const KinectEstimate& k : result_->kinects) {
    for (int i = 0; i < kKinectParameterCount; ++i) {
      if (!weak(k.parameters[i])) continue;
      switch (i) {
        case kYaw: return SessionStep::kStraight;
        case kX: case kY: case kLatency: return SessionStep::kTurn;
        default: return SessionStep::kFloor;  // Roll, pitch, height.
      }
    }
  }
  if (weak(result_->scale_left) || weak(result_->scale_right)) return SessionStep::kStraight;
  return std::nullopt;
}

robotio::Status CalibrationSession::Save(const std::string& file, bool allow_uncalibrated) {
  if (!result_ || (step_ != SessionStep::kReview && step_ != SessionStep::kSave)) {
    return robotio::Error{"calibration session: nothing to save yet; solve and review first"};
  }
  if (!result_->AllCalibrated() && !allow_uncalibrated) {
    std::string names;
    for (const std::string& w : result_->warnings) names += "\n  " + w;
    return robotio::Error{"calibration session: refusing to write " + file +
                          ": not every parameter is calibrated:" + names};
  }
  const robotio::Status status = robotio::SaveRig(result_->ToRig(guess_), file);
  if (status.ok()) step_ = SessionStep::kDone;
  return status;
}

}  // namespace dynamap::calibration
