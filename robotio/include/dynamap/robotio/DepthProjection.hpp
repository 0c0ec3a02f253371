// Depth image → 3D points in the sensor's optical frame or in base (thesis 5.1).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::robotio {

using PointList = std::vector<Eigen::Vector3f>;

// Organised cloud (width * height, row-major) in the optical frame, NaN where depth is 0:
// x = (u - cx) / fx * z, y = (v - cy) / fy * z, z = depth.
[[nodiscard]] PointList DepthToOrganizedPoints(const DepthFrame& frame);

// Valid points only, within [min_range, max_range] along z, in the optical frame.
[[nodiscard]] PointList DepthToPoints(const DepthFrame& frame, double min_range_m,
                                      double max_range_m);

// Valid points of the mount's range, transformed into base with T_base_kinect.
[[nodiscard]] PointList DepthToBasePoints(const DepthFrame& frame, const KinectMount& mount);

// Every pixel with a measurement as a ray: origin and end point in the target frame,
// `hit` false for returns beyond max range (a depth, along the optical axis z, as the Kinect
// measures it: the ray is cut where its depth reaches max range, no endpoint).
struct DepthRays {
  Eigen::Vector3f origin;
  PointList ends;
  std::vector<bool> hit;
  // Per ray, |cos| of the angle between the ray and the normal of the surface it hit (1 =
  // head-on, towards 0 = grazing), from the neighbouring pixels; 0 when they give no
  // normal. A ray cut at max range carries the incidence of the surface measured beyond.
  // Empty when no ray has it (rays made from points).
  std::vector<float> incidence_cos;
  // Per ray, m from the origin to the measured surface: the end's distance for a hit,
  // farther for a ray cut at max range (its surface lies beyond). Empty with incidence_cos.
  std::vector<float> surface_range_m;
  // Per ray, m from the origin to where the ray comes within `alongside_m` of the nearest
  // surface measured (or assumed, EdgeClearance) beside it, its own included
  // (NearestDepthAlongside, along the ray). Empty without EdgeClearance::lateral_m.
  std::vector<float> alongside_range_m;
};

// What DepthToRays looks for beside each ray (DepthEdges.hpp); all off by default.
struct EdgeClearance {
  double lateral_m = 0.0;  // NearestDepthAlongside's distance; 0 = no alongside_range_m.
  int grazing_gap_px = 0;  // FillGrazingGaps's reach; 0 = gaps stay gaps.
  // Only grazing pixels whose point lies at least this high in the target frame fill gaps
  // (the floor seen far off is grazing too, and has its own rule in the map).
  double gap_min_height_m = -std::numeric_limits<double>::infinity();
  // Beside the image's left and right edges, a surface as near as this (m) may lie unseen
  // (NearestDepthAlongside's side_depth_m); 0 = nothing is assumed there.
  double side_depth_m = 0.0;
};

[[nodiscard]] DepthRays DepthToRays(const DepthFrame& frame, const KinectMount& mount,
                                    const Eigen::Isometry3d& T_target_base, int stride = 1,
                                    const EdgeClearance& edges = {});

}  // namespace dynamap::robotio
