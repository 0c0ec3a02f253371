#include "SyntheticCapture.hpp"

#include <cmath>

#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::calibration::test {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kRampS = 0.8;     // s to reach a segment's plateau speed.
constexpr double kDtS = 0.001;     // s, integration step of the true motion.
constexpr std::int64_t kNs = 1000000000;

struct TruthSample {
  double t = 0.0;
  robotio::Pose2D pose;
  double left = 0.0, right = 0.0;  // True cumulative wheel distances.
  double omega = 0.0;
};

}  // namespace

std::vector<Segment> GuidedSegments() {
  return {{0.0, 0.0, 1.0, CaptureStep::kFloor},       {0.0, 0.6, 6.0, CaptureStep::kTurn},
          {0.0, -0.6, 6.0, CaptureStep::kTurn},       {0.35, 0.0, 7.0, CaptureStep::kStraight},
          {-0.35, 0.0, 7.0, CaptureStep::kStraight},  {0.3, 0.4, 5.0, CaptureStep::kArcs},
          {0.3, -0.4, 5.0, CaptureStep::kArcs},       {0.2, 0.8, 3.0, CaptureStep::kArcs}};
}

robotio::Rig TrueRig() {
  robotio::Rig rig;
  robotio::KinectMount front;
  front.id = "kinect0";
  front.T_base_kinect = robotio::MountPose({0.12, 0.03, 0.62}, Eigen::Vector3d(178.0, 12.0, 4.0) * kDeg);
  front.latency_s = 0.1;
  robotio::KinectMount rear;
  rear.id = "kinect1";
  rear.T_base_kinect =
      robotio::MountPose({-0.10, -0.02, 0.58}, Eigen::Vector3d(-179.0, 10.0, 176.0) * kDeg);
  rear.latency_s = 0.1;
  rig.kinects = {front, rear};
  return rig;
}

robotio::Rig PerturbedRig(const robotio::Rig& truth, double max_angle_rad, double max_offset_m,
                          double guess_latency_s, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  robotio::Rig guess = truth;
  for (robotio::KinectMount& m : guess.kinects) {
    Eigen::Vector3d rpy = robotio::MountRollPitchYaw(m.T_base_kinect);
    Eigen::Vector3d t = m.T_base_kinect.translation();
    for (int i = 0; i < 3; ++i) {
      rpy[i] += max_angle_rad * unit(rng);
      t[i] += max_offset_m * unit(rng);
    }
    m.T_base_kinect = robotio::MountPose(t, rpy);
    m.latency_s = guess_latency_s;
  }
  return guess;
}

CaptureData Synthesize(const robotio::Rig& truth, const robotio::Rig& guess,
                       const SyntheticOptions& options) {
  constexpr double kTrackWidth = 0.5;
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> gauss(0.0, 1.0);

  // True motion with trapezoid-like ramps (smooth speed changes make latency observable).
  std::vector<TruthSample> truth_samples;
  std::vector<CaptureStep> steps;
  TruthSample s;
  truth_samples.push_back(s);
  steps.push_back(CaptureStep::kFloor);
  for (const Segment& seg : options.segments) {
    const int n = static_cast<int>(seg.duration_s / kDtS);
    for (int i = 0; i < n; ++i) {
      const double tau = i * kDtS;
      const double ramp = std::min({1.0, tau / kRampS, (seg.duration_s - tau) / kRampS});
      const double v = seg.v * ramp;
      const double w = seg.omega * ramp;
      s.pose = s.pose.Compose({v * kDtS, 0.0, w * kDtS});
      s.left += (v - 0.5 * kTrackWidth * w) * kDtS;
      s.right += (v + 0.5 * kTrackWidth * w) * kDtS;
      s.omega = w;
      s.t += kDtS;
      truth_samples.push_back(s);
      steps.push_back(seg.step);
    }
  }

  CaptureData capture;
  capture.track_width_m = kTrackWidth;
  for (std::size_t i = 0; i < truth_samples.size(); i += 20) {  // Odometry at 50 Hz.
    const TruthSample& t = truth_samples[i];
    capture.odometry.push_back({static_cast<std::int64_t>(std::llround(t.t * kNs)),
                                t.left / options.scale_left, t.right / options.scale_right});
  }
  for (std::size_t i = 0; i < truth_samples.size(); i += 5) {  // Gyro at 200 Hz.
    const TruthSample& t = truth_samples[i];
    capture.imu.push_back({static_cast<std::int64_t>(std::llround(t.t * kNs)), 0.0, 0.0,
                           t.omega + 0.002 * gauss(rng)});
  }

  const auto pose_at = [&](double t) {
    const auto i = static_cast<std::size_t>(std::clamp(t / kDtS, 0.0,
                                                       double(truth_samples.size() - 1)));
    return truth_samples[i].pose;
  };
  const int stride = static_cast<int>(std::lround(options.keyframe_interval_s / kDtS));
  for (std::size_t k = 0; k < truth.kinects.size(); ++k) {
    const robotio::KinectMount& mount = truth.kinects[k];
    KinectCapture kc;
    kc.guess = guess.kinects[k];
    const Eigen::Isometry3d X = mount.T_base_kinect;
    for (int f = 0; f < 20; ++f) {
      PlaneFit fit;
      fit.ok = true;
      const Eigen::Vector3d noise(gauss(rng), gauss(rng), gauss(rng));
      fit.normal = (X.linear().transpose() * Eigen::Vector3d::UnitZ() +
                    options.floor_normal_noise_rad * noise).normalized();
      fit.distance_m = X.translation().z() + options.floor_distance_noise_m * gauss(rng);
      fit.inliers = fit.points = 1000;
      fit.inlier_share = 1.0;
      kc.floor.push_back(fit);
    }
    // Pairs start at a per-Kinect offset so the two Kinects' frames interleave.
    for (std::size_t i = 20 + 7 * k; i + stride < truth_samples.size(); i += stride) {
      const double t0 = truth_samples[i].t, t1 = truth_samples[i + stride].t;
      const Eigen::Isometry3d B = pose_at(t0).Between(pose_at(t1)).ToIsometry();
      Eigen::Isometry3d A = X.inverse() * B * X;
      const Eigen::Vector3d rot_noise(gauss(rng), gauss(rng), gauss(rng));
      const Eigen::Vector3d trans_noise(gauss(rng), gauss(rng), gauss(rng));
      A.linear() = A.linear() * Eigen::AngleAxisd(options.rotation_noise_rad * rot_noise.norm(),
                                                  rot_noise.normalized())
                                    .toRotationMatrix();
      A.translation() += options.translation_noise_m * trans_noise;
      MotionPair pair;
      pair.step = steps[i];
      pair.from_received_ns = std::llround((t0 + mount.latency_s) * kNs);
      pair.to_received_ns = std::llround((t1 + mount.latency_s) * kNs);
      pair.T_from_to = A;
      pair.structure = 0.5;
      kc.motions.push_back(pair);
    }
    capture.kinects.push_back(kc);
  }
  return capture;
}

}  // namespace dynamap::calibration::test
