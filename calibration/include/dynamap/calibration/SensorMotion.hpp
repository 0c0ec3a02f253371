// A Kinect's own motion between two of its frames by point-to-plane ICP (thesis 8.2, the
// "alias transformation"), with a structure measure that says whether the scene pins all
// six degrees of freedom (a bare floor or a single wall does not).
#pragma once

#include <Eigen/Geometry>

#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::calibration {

struct IcpConfig {
  double voxel_m = 0.05;                // m, voxel-grid downsampling of each cloud.
  double normal_radius_m = 0.15;        // m, neighbourhood for surface normals.
  double max_correspondence_m = 0.2;    // m, farthest point pairing ICP accepts.
  double fine_correspondence_m = 0.05;  // m, the same in a second stage (0: no second stage).
  int max_iterations = 50;              // ICP iterations at most.
  double max_rms_m = 0.03;              // m, point-to-plane RMS above which a pair is rejected.
  double min_structure = 0.01;          // Smallest/largest information eigenvalue ratio.
  int min_correspondences = 200;        // Paired points below which a pair is rejected.
};

// A downsampled cloud with unit normals, optical frame (prepared once per frame).
struct PreparedCloud {
  robotio::PointList points;
  robotio::PointList normals;
};

[[nodiscard]] PreparedCloud PrepareCloud(const robotio::PointList& points, const IcpConfig& config);

struct SensorMotionResult {
  bool accepted = false;   // Converged, fits within max_rms_m and has enough structure.
  // Pose of the `to` frame in the `from` frame: maps `to` points into the `from` frame.
  Eigen::Isometry3d T_from_to = Eigen::Isometry3d::Identity();
  double rms_m = 0.0;      // m, point-to-plane RMS at the solution.
  double structure = 0.0;  // 0..1, see IcpConfig::min_structure.
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Identity();
  double lever_m = 1.0;    // See MotionPair::information.
  int correspondences = 0;
};

// `guess` is the expected T_from_to (from odometry through the rig guess).
[[nodiscard]] SensorMotionResult EstimateSensorMotion(const PreparedCloud& from,
                                                      const PreparedCloud& to,
                                                      const Eigen::Isometry3d& guess,
                                                      const IcpConfig& config);

}  // namespace dynamap::calibration
