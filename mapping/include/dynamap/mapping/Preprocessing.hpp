// Scan preprocessing before registration (thesis 5.3): both Kinects' depth → points in
// base through the rig → voxel-grid filter → drop points in dynamic-occupied voxels.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::mapping {

// Every point moved by T (to the frame T maps into).
[[nodiscard]] robotio::PointList TransformedPoints(const robotio::PointList& points,
                                                   const Eigen::Isometry3d& T);

// One point per occupied voxel of edge `leaf_m` (the centroid of its points), PCL's
// VoxelGrid; non-finite points are dropped. leaf_m <= 0 returns the input.
[[nodiscard]] robotio::PointList VoxelGridFilter(const robotio::PointList& points, double leaf_m);

// Keeps the points (base frame) whose voxel, seen from base pose T_map_base, is not
// occupied in the dynamic map.
[[nodiscard]] robotio::PointList RemoveDynamicPoints(const robotio::PointList& points_base,
                                                     const DualMap& map,
                                                     const Eigen::Isometry3d& T_map_base);

// Keeps the points whose voxel is neither occupied in the dynamic map nor free in the
// static map: a point in space seen free before is something that has appeared there (a
// person walking into view) even before the dynamic map knows it. Surfaces stay: the
// free space stops surface_margin_voxels short of them, so a point predicted up to that
// far in front of its surface still lands in a voxel that is not free.
[[nodiscard]] robotio::PointList RemovePointsOfChange(const robotio::PointList& points_base,
                                                      const DualMap& map,
                                                      const Eigen::Isometry3d& T_map_base);

// The whole step for one time instant: frames[i] from rig.kinects[frames[i].sensor_id],
// merged in base, filtered with config.voxel_filter_m, dynamic points removed.
[[nodiscard]] robotio::PointList PreprocessScan(const std::vector<robotio::DepthFrame>& frames,
                                                const robotio::Rig& rig, const DualMap& map,
                                                const Eigen::Isometry3d& T_map_base);

}  // namespace dynamap::mapping
