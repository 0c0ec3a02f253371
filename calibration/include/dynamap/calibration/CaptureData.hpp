// What the calibration solver consumes: per Kinect its guessed mount, floor-plane fits and
// sensor motions between frames (thesis 8.2, the "alias transformations"), plus the raw
// odometry and gyro streams of the same capture.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <vector>

#include "dynamap/calibration/FloorPlane.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::calibration {

// Capture steps of the guided session, also used to tag data for plots and coverage.
enum class CaptureStep { kFloor = 0, kTurn = 1, kStraight = 2, kArcs = 3 };

// One Kinect's own motion between two of its frames, from ICP.
struct MotionPair {
  CaptureStep step = CaptureStep::kTurn;  // Kind of base motion (turn, straight, arc).
  std::int64_t from_received_ns = 0;      // Receive stamp of the earlier frame.
  std::int64_t to_received_ns = 0;        // Receive stamp of the later frame.
  // The sensor's pose at `to` in its own optical frame at `from` (maps `to` points into
  // the `from` frame): T_kinect(from)_kinect(to).
  Eigen::Isometry3d T_from_to = Eigen::Isometry3d::Identity();
  double rms_m = 0.0;      // m, point-to-plane RMS of the ICP fit.
  double structure = 0.0;  // Smallest/largest eigenvalue of the ICP information, 0..1.
  // How well the scene pins each direction of the motion: the ICP's point-to-plane
  // information for a perturbation exp(lever·ω, v) applied in the `from` frame, rotation
  // scaled by lever_m so both blocks are metres, divided by its largest eigenvalue. A
  // direction along a bare wall has ~0 there and the solver gives its error no weight.
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Identity();
  double lever_m = 2.5;  // m, RMS distance of the paired points from the sensor.
};

struct KinectCapture {
  robotio::KinectMount guess;           // The operator's rig guess for this Kinect.
  std::vector<PlaneFit> floor;          // Per-frame floor fits in the optical frame.
  std::vector<MotionPair> motions;      // Accepted ICP pairs, in time order.
};

struct CaptureData {
  std::vector<KinectCapture> kinects;                // Rig order.
  std::vector<robotio::OdometryReading> odometry;    // Sorted by stamp.
  std::vector<robotio::ImuReading> imu;              // Sorted by stamp.
  double gyro_bias_rad_s = 0.0;  // rad/s about base z, measured while standing still.
  // m, nominal distance between the wheel contact points. With the gyro giving heading,
  // only the wheels' heading (s_r·Δr − s_l·Δl)/track separates the two scales: their
  // difference otherwise looks exactly like a sideways Kinect offset.
  double track_width_m = 0.5;
};

}  // namespace dynamap::calibration
