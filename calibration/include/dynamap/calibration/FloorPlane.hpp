// Floor-plane step of the rig calibration (thesis 8.3): a RANSAC plane fit per Kinect
// while the robot stands still gives the Kinect's roll, pitch and height in base.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <vector>

#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::calibration {

struct PlaneFitConfig {
  double distance_threshold_m = 0.03;  // m, RANSAC inlier band on either side of the plane.
  int max_iterations = 1000;           // RANSAC hypotheses at most.
  double probability = 0.99;           // Wanted chance of drawing one all-inlier sample.
  // rad, when an expected normal is given: planes tilted further from it are rejected, so
  // a wall never passes for the floor.
  double max_normal_deviation_rad = 0.35;
  bool refine = true;  // Least-squares refit of the plane on the RANSAC inliers.
  // With refine: refits on a band narrowed to narrowing_sigmas × the inliers' robust
  // spread (at least min_band_m), so points just above the floor do not tilt it.
  int narrowing_rounds = 3;
  double narrowing_sigmas = 2.5;
  double min_band_m = 0.004;  // m.
};

// A plane n·p + d = 0 in the frame of the points, n unit length and oriented so that d >= 0
// (the frame's origin, i.e. the sensor, lies on the side n points to).
struct PlaneFit {
  bool ok = false;                                // A plane with >= 3 inliers was found.
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // Unit normal, points' frame.
  double distance_m = 0.0;                        // m, origin's distance from the plane.
  std::size_t inliers = 0;                        // Points within the inlier band.
  std::size_t points = 0;                         // Points offered to the fit.
  double inlier_share = 0.0;                      // inliers / points.
  double rms_m = 0.0;                             // m, RMS point-plane distance of inliers.
};

[[nodiscard]] PlaneFit FitPlane(const robotio::PointList& points, const PlaneFitConfig& config,
                                const std::optional<Eigen::Vector3d>& expected_normal = {});

// The floor's normal (base +z) as the Kinect would see it if mounted as `T_base_kinect`.
[[nodiscard]] Eigen::Vector3d FloorNormalInKinect(const Eigen::Isometry3d& T_base_kinect);

// What a floor plane seen in a Kinect's optical frame says about its mount.
struct FloorPose {
  double roll_rad = 0.0;    // rad, body-frame roll in base (robotio::MountPose convention).
  double pitch_rad = 0.0;   // rad, body-frame pitch in base.
  double height_m = 0.0;    // m, optical centre above the floor (base z).
  double inlier_share = 0.0;  // Mean over the frames used.
  double rms_m = 0.0;         // m, mean plane RMS over the frames used.
  int frames = 0;             // Plane fits combined.
};

// Roll and pitch follow from the normal alone (yaw does not change the floor's look).
[[nodiscard]] FloorPose FloorPoseFromPlane(const PlaneFit& plane);
// Averages the normals and distances of successful per-frame fits; frames == 0 if none.
[[nodiscard]] FloorPose CombineFloorFits(const std::vector<PlaneFit>& fits);

}  // namespace dynamap::calibration
