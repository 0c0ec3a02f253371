#include "dynamap/calibration/HandEye.hpp"

#include <Eigen/QR>
#include <cmath>

#include "dynamap/robotio/Rig.hpp"

namespace dynamap::calibration {

PlanarHandEye SolvePlanarHandEye(const std::vector<MotionCorrespondence>& pairs,
                                 double roll_rad, double pitch_rad, const PlanarHandEye& guess,
                                 bool solve_yaw, bool solve_translation) {
  PlanarHandEye result = guess;
  result.ok = false;
  if (pairs.empty() || (!solve_yaw && !solve_translation)) return result;
  // Levelled sensor frame: the mount without yaw, so its motions are (nearly) planar.
  const Eigen::Matrix3d R_tilt =
      robotio::MountPose(Eigen::Vector3d::Zero(), {roll_rad, pitch_rad, 0.0}).linear();
  const Eigen::Rotation2Dd R_yaw_guess(guess.yaw_rad);
  const Eigen::Vector2d p_guess(guess.x_m, guess.y_m);
  const int yaw_cols = solve_yaw ? 2 : 0;
  const int cols = yaw_cols + (solve_translation ? 2 : 0);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * pairs.size(), cols);
  Eigen::VectorXd b(2 * pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const Eigen::Vector2d t_a = (R_tilt * pairs[i].sensor_motion.translation()).head<2>();
    const Eigen::Matrix3d& R_b = pairs[i].base_motion.linear();
    const double phi = std::atan2(R_b(1, 0), R_b(0, 0));
    const double c = std::cos(phi);
    const double s = std::sin(phi);
    Eigen::Matrix2d I_minus_R;
    I_minus_R << 1.0 - c, s, -s, 1.0 - c;
    Eigen::Vector2d rhs = pairs[i].base_motion.translation().head<2>();
    const auto r = static_cast<Eigen::Index>(2 * i);
    // Known terms move to the right-hand side.
    if (solve_yaw) {
      A(r, 0) = t_a.x();
      A(r, 1) = -t_a.y();
      A(r + 1, 0) = t_a.y();
      A(r + 1, 1) = t_a.x();
    } else {
      rhs -= R_yaw_guess * t_a;
    }
    if (solve_translation) {
      A.block<2, 2>(r, yaw_cols) = I_minus_R;
    } else {
      rhs -= I_minus_R * p_guess;
    }
    b.segment<2>(r) = rhs;
  }
  const Eigen::VectorXd x = A.colPivHouseholderQr().solve(b);
  if (!x.allFinite()) return result;
  if (solve_yaw) {
    if (x.head<2>().norm() < 1e-9) return result;
    result.yaw_rad = std::atan2(x(1), x(0));
  }
  if (solve_translation) {
    result.x_m = x(yaw_cols);
    result.y_m = x(yaw_cols + 1);
  }
  result.ok = true;
  return result;
}

}  // namespace dynamap::calibration
