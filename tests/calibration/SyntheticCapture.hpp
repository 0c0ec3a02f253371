// A synthetic calibration capture with known truth: a scripted drive (turns, straight,
// arcs) with smooth speed ramps, odometry with wheel scale errors, a gyro, and per Kinect
// the exact sensor motions (plus noise) and floor planes that a true rig would produce.
#pragma once

#include <cstdint>
#include <random>
#include <vector>

#include "dynamap/calibration/CaptureData.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::calibration::test {

struct Segment {
  double v = 0.0;        // m/s plateau.
  double omega = 0.0;    // rad/s plateau.
  double duration_s = 0.0;
  CaptureStep step = CaptureStep::kTurn;
};

struct SyntheticOptions {
  std::vector<Segment> segments;     // Driven in order, each ramped up and down.
  double keyframe_interval_s = 0.5;  // s between the two frames of a pair.
  double rotation_noise_rad = 0.0005;
  double translation_noise_m = 0.0015;  // As SolverConfig::translation_sigma_m.
  double floor_normal_noise_rad = 0.0005;
  double floor_distance_noise_m = 0.001;
  double scale_left = 1.004;         // True wheel distance = scale × reported.
  double scale_right = 0.996;
  unsigned seed = 1;
};

// The standard guided sequence: still, turn both ways, straight, arcs both ways.
std::vector<Segment> GuidedSegments();

robotio::Rig TrueRig();
// `truth` perturbed by up to `max_angle_rad` per angle and `max_offset_m` per axis, latency
// set to `guess_latency_s`.
robotio::Rig PerturbedRig(const robotio::Rig& truth, double max_angle_rad, double max_offset_m,
                          double guess_latency_s, unsigned seed);

CaptureData Synthesize(const robotio::Rig& truth, const robotio::Rig& guess,
                       const SyntheticOptions& options);

}  // namespace dynamap::calibration::test
