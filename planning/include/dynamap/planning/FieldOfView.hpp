// Where the Kinects of a rig can see at robot height, seen from above: what ObstacleMemory
// may forget for not seeing it again. Occlusion is not modelled (a point behind a nearer
// one counts as in view).
#pragma once

#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "dynamap/robotio/Rig.hpp"

namespace dynamap::planning {

class FieldOfView {
 public:
  // The height band (base z) a point stands for: a post is in view when some of it is.
  FieldOfView(const robotio::Rig& rig, double min_height_m, double max_height_m);

  // Whether a Kinect sees some height of the band at `p_base` (x, y in base): it projects
  // into its image `margin_px` or more inside the border, at a depth the Kinect measures
  // with `margin_m` to spare.
  [[nodiscard]] bool Sees(const Eigen::Vector2d& p_base, double margin_px = 2.0,
                          double margin_m = 0.05) const;

 private:
  struct Camera {
    Eigen::Isometry3d T_kinect_base;
    robotio::KinectMount mount;
  };
  std::vector<Camera> cameras_;
  std::vector<double> heights_;  // Heights of the band tried.
};

}  // namespace dynamap::planning
