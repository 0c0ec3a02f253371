// Ceres residuals of the rig solver (private): hand-eye consistency of one ICP pair with the
// time-shifted, re-scaled odometry, and agreement of a mount with the floor plane.
#pragma once

#include <ceres/ceres.h>
#include <ceres/cubic_interpolation.h>
#include <ceres/rotation.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace dynamap::calibration::internal {

using TrackGrid = ceres::Grid1D<double, 5>;
using TrackInterpolator = ceres::CubicInterpolator<TrackGrid>;

// R_base_optical = Rz(yaw)·Ry(pitch)·Rx(roll)·BodyFromOptical, pose = (roll, pitch, yaw, ...).
template <typename T>
Eigen::Matrix<T, 3, 3> MountRotation(const T* pose) {
  using std::cos;
  using std::sin;
  const T cr = cos(pose[0]), sr = sin(pose[0]);
  const T cp = cos(pose[1]), sp = sin(pose[1]);
  const T cy = cos(pose[2]), sy = sin(pose[2]);
  Eigen::Matrix<T, 3, 3> R;
  R << cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr,  //
      sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr,   //
      -sp, cp * sr, cp * cr;
  Eigen::Matrix<T, 3, 3> body_from_optical;
  body_from_optical << T(0), T(0), T(1), T(-1), T(0), T(0), T(0), T(-1), T(0);
  return R * body_from_optical;
}

// The ICP motion A of a Kinect between receive times r0 and r1 must equal X⁻¹·B·X, where X
// is the mount and B the base motion between the capture times r − latency, built from the
// track with the current wheel scales. The error is the left perturbation δ = (ω, v) with
// prediction = exp(δ)·A, in the `from` frame where the ICP information was computed; it
// is weighted by that information (rotation times the lever, so both blocks are metres)
// and divided by the translation sigma. With identity weight, lever 1 and sigma 1 the
// residual is (ω in rad, v in m).
class HandEyeResidual {
 public:
  using Matrix6 = Eigen::Matrix<double, 6, 6>;

  HandEyeResidual(const TrackInterpolator* track, double rate_hz, double t0_s, double t1_s,
                  const Eigen::Isometry3d& A, const Matrix6& information, double lever_m,
                  double translation_sigma)
      : track_(track), rate_hz_(rate_hz), t0_s_(t0_s), t1_s_(t1_s), A_(A), lever_m_(lever_m),
        inv_sigma_(1.0 / translation_sigma) {
    // Square root W with WᵀW = information (negative round-off eigenvalues count as 0).
    const Eigen::SelfAdjointEigenSolver<Matrix6> eigen(information);
    const Eigen::Matrix<double, 6, 1> root = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
    weight_ = root.asDiagonal() * eigen.eigenvectors().transpose();
  }

  template <typename T>
  bool operator()(const T* pose, const T* latency, const T* scales, T* residual) const {
    T f0[5], f1[5];
    track_->Evaluate((T(t0_s_) - latency[0]) * T(rate_hz_), f0);
    track_->Evaluate((T(t1_s_) - latency[0]) * T(rate_hz_), f1);
    using std::cos;
    using std::sin;
    const T dx = scales[0] * (f1[1] - f0[1]) + scales[1] * (f1[3] - f0[3]);
    const T dy = scales[0] * (f1[2] - f0[2]) + scales[1] * (f1[4] - f0[4]);
    const T c0 = cos(f0[0]), s0 = sin(f0[0]);
    const T dtheta = f1[0] - f0[0];
    Eigen::Matrix<T, 3, 3> R_b = Eigen::Matrix<T, 3, 3>::Identity();
    R_b(0, 0) = cos(dtheta);
    R_b(0, 1) = -sin(dtheta);
    R_b(1, 0) = sin(dtheta);
    R_b(1, 1) = cos(dtheta);
    const Eigen::Matrix<T, 3, 1> t_b(c0 * dx + s0 * dy, -s0 * dx + c0 * dy, T(0));

    const Eigen::Matrix<T, 3, 3> R_x = MountRotation(pose);
    const Eigen::Matrix<T, 3, 1> t_x(pose[3], pose[4], pose[5]);
    const Eigen::Matrix<T, 3, 3> R_pred = R_x.transpose() * R_b * R_x;
    const Eigen::Matrix<T, 3, 1> t_pred = R_x.transpose() * (R_b * t_x + t_b - t_x);

    const Eigen::Matrix<T, 3, 3> R_err = R_pred * A_.linear().cast<T>().transpose();
    T angle_axis[3];
    ceres::RotationMatrixToAngleAxis(ceres::ColumnMajorAdapter3x3(R_err.data()), angle_axis);
    const Eigen::Matrix<T, 3, 1> v = t_pred - R_err * A_.translation().cast<T>();
    Eigen::Matrix<T, 6, 1> delta;
    delta << angle_axis[0] * T(lever_m_), angle_axis[1] * T(lever_m_),
        angle_axis[2] * T(lever_m_), v[0], v[1], v[2];
    const Eigen::Matrix<T, 6, 1> weighted = weight_.cast<T>() * delta;
    for (int i = 0; i < 6; ++i) residual[i] = weighted[i] * T(inv_sigma_);
    return true;
  }

 private:
  const TrackInterpolator* track_;
  double rate_hz_;
  double t0_s_;
  double t1_s_;
  Eigen::Isometry3d A_;
  Matrix6 weight_;
  double lever_m_;
  double inv_sigma_;
};

// Over one stretch of the capture, the heading change the scaled wheels imply must equal
// the gyro's.
class WheelHeadingResidual {
 public:
  WheelHeadingResidual(double left_m, double right_m, double gyro_dtheta, double track_m,
                       double sigma_rad)
      : left_m_(left_m), right_m_(right_m), gyro_dtheta_(gyro_dtheta), track_m_(track_m),
        inv_sigma_(1.0 / sigma_rad) {}

  template <typename T>
  bool operator()(const T* scales, T* residual) const {
    residual[0] = ((scales[1] * T(right_m_) - scales[0] * T(left_m_)) / T(track_m_) -
                   T(gyro_dtheta_)) *
                  T(inv_sigma_);
    return true;
  }

 private:
  double left_m_, right_m_, gyro_dtheta_, track_m_, inv_sigma_;
};

// The floor (base z = 0, normal +z) seen from the mount must match the fitted plane
// (unit normal n towards the sensor, distance d): n = R_xᵀ·e_z and d = z.
class FloorResidual {
 public:
  FloorResidual(const Eigen::Vector3d& normal, double distance_m, double normal_sigma,
                double distance_sigma)
      : normal_(normal), distance_m_(distance_m), inv_normal_sigma_(1.0 / normal_sigma),
        inv_distance_sigma_(1.0 / distance_sigma) {}

  template <typename T>
  bool operator()(const T* pose, T* residual) const {
    const Eigen::Matrix<T, 3, 3> R_x = MountRotation(pose);
    for (int i = 0; i < 3; ++i) {
      residual[i] = (R_x(2, i) - T(normal_[i])) * T(inv_normal_sigma_);
    }
    residual[3] = (pose[5] - T(distance_m_)) * T(inv_distance_sigma_);
    return true;
  }

 private:
  Eigen::Vector3d normal_;
  double distance_m_;
  double inv_normal_sigma_;
  double inv_distance_sigma_;
};

}  // namespace dynamap::calibration::internal
