// Planar robot pose (x, y, theta) in the map frame and its composition rules
// (thesis 5.2: the base moves in a plane).
#pragma once

#include <Eigen/Geometry>

namespace dynamap::robotio {

struct Pose2D {
  double x = 0.0;      // m, map frame.
  double y = 0.0;      // m, map frame.
  double theta = 0.0;  // rad, heading about map z, counter-clockwise from map x.

  // this ⊕ delta: delta expressed in this pose's frame.
  [[nodiscard]] Pose2D Compose(const Pose2D& delta) const;
  [[nodiscard]] Pose2D Inverse() const;
  // The pose of `other` expressed in this pose's frame (this⁻¹ ⊕ other).
  [[nodiscard]] Pose2D Between(const Pose2D& other) const;
  // The same pose as a 3D rigid transform (z = 0, rotation about z).
  [[nodiscard]] Eigen::Isometry3d ToIsometry() const;
  [[nodiscard]] static Pose2D FromIsometry(const Eigen::Isometry3d& T);
};

// Wraps an angle to (-pi, pi].
[[nodiscard]] double WrapAngle(double angle);

// Linear interpolation between two poses (heading along the shorter arc), s in [0, 1].
[[nodiscard]] Pose2D Interpolate(const Pose2D& a, const Pose2D& b, double s);

}  // namespace dynamap::robotio
