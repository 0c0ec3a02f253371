#include "dynamap/robotio/Pose2D.hpp"

#include <cmath>

namespace dynamap::robotio {

double WrapAngle(double angle) {
  angle = std::fmod(angle + M_PI, 2.0 * M_PI);
  if (angle <= 0.0) angle += 2.0 * M_PI;
  return angle - M_PI;
}

Pose2D Pose2D::Compose(const Pose2D& delta) const {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  return {x + c * delta.x - s * delta.y, y + s * delta.x + c * delta.y,
          WrapAngle(theta + delta.theta)};
}

Pose2D Pose2D::Inverse() const {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  return {-c * x - s * y, s * x - c * y, WrapAngle(-theta)};
}

Pose2D Pose2D::Between(const Pose2D& other) const { return Inverse().Compose(other); }

Eigen::Isometry3d Pose2D::ToIsometry() const {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  T.translation() = Eigen::Vector3d(x, y, 0.0);
  return T;
}

Pose2D Pose2D::FromIsometry(const Eigen::Isometry3d& T) {
  const Eigen::Vector3d x_axis = T.linear().col(0);
  return {T.translation().x(), T.translation().y(), std::atan2(x_axis.y(), x_axis.x())};
}

Pose2D Interpolate(const Pose2D& a, const Pose2D& b, double s) {
  return {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y),
          WrapAngle(a.theta + s * WrapAngle(b.theta - a.theta))};
}

}  // namespace dynamap::robotio
