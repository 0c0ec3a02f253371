// Closed-form first estimate of a Kinect's yaw and x/y in base from the planar hand-eye
// relation X·A = B·X (thesis 8.4–8.5), given roll and pitch from the floor plane.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace dynamap::calibration {

// One interval: the sensor's motion A (optical frame) and the base's motion B (planar, as
// a 3D transform) over the same time.
struct MotionCorrespondence {
  Eigen::Isometry3d sensor_motion = Eigen::Isometry3d::Identity();  // T_k(from)_k(to).
  Eigen::Isometry3d base_motion = Eigen::Isometry3d::Identity();    // T_b(from)_b(to).
};

struct PlanarHandEye {
  bool ok = false;         // Enough motion to solve anything.
  double yaw_rad = 0.0;    // rad, body yaw in base.
  double x_m = 0.0;        // m, base x (the guess when !solve_translation).
  double y_m = 0.0;        // m, base y (the guess when !solve_translation).
};

// Levels each sensor motion with roll/pitch, then solves the linear least-squares problem
// R(yaw)·t_A + (I − R_B)·p = t_B for (cos yaw, sin yaw, p). Without turning (I − R_B)
// vanishes, so `solve_translation` false keeps p at the guess; without driving, pure
// turns only fix p in the sensor's own heading, so `solve_yaw` false keeps the guessed yaw.
[[nodiscard]] PlanarHandEye SolvePlanarHandEye(const std::vector<MotionCorrespondence>& pairs,
                                               double roll_rad, double pitch_rad,
                                               const PlanarHandEye& guess, bool solve_yaw,
                                               bool solve_translation);

}  // namespace dynamap::calibration
