#include "dynamap/mapping/Preprocessing.hpp"

#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace dynamap::mapping {

robotio::PointList TransformedPoints(const robotio::PointList& points, const Eigen::Isometry3d& T) {
  const Eigen::Isometry3f Tf = T.cast<float>();
  robotio::PointList out;
  out.reserve(points.size());
  for (const Eigen::Vector3f& p : points) out.push_back(Tf * p);
  return out;
}

robotio::PointList VoxelGridFilter(const robotio::PointList& points, double leaf_m) {
  if (leaf_m <= 0.0) return points;
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  cloud->reserve(points.size());
  for (const Eigen::Vector3f& p : points) {
    if (p.allFinite()) cloud->push_back(pcl::PointXYZ(p.x(), p.y(), p.z()));
  }
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  const auto leaf = static_cast<float>(leaf_m);
  grid.setLeafSize(leaf, leaf, leaf);
  grid.setInputCloud(cloud);
  pcl::PointCloud<pcl::PointXYZ> filtered;
  grid.filter(filtered);
  robotio::PointList result;
  result.reserve(filtered.size());
  for (const pcl::PointXYZ& p : filtered) result.emplace_back(p.x, p.y, p.z);
  return result;
}

namespace {

// The points (base frame) for whose position in the map `keep` holds.
template <typename Keep>
robotio::PointList KeepPoints(const robotio::PointList& points_base,
                              const Eigen::Isometry3d& T_map_base, Keep keep) {
  const Eigen::Isometry3f T = T_map_base.cast<float>();
  robotio::PointList kept;
  kept.reserve(points_base.size());
  for (const Eigen::Vector3f& p : points_base) {
    if (keep(T * p)) kept.push_back(p);
  }
  return kept;
}

}  // namespace

robotio::PointList RemoveDynamicPoints(const robotio::PointList& points_base, const DualMap& map,
                                       const Eigen::Isometry3d& T_map_base) {
  return KeepPoints(points_base, T_map_base,
                    [&map](const Eigen::Vector3f& p_map) { return !map.IsDynamicOccupied(p_map); });
}

robotio::PointList RemovePointsOfChange(const robotio::PointList& points_base, const DualMap& map,
                                        const Eigen::Isometry3d& T_map_base) {
  return KeepPoints(points_base, T_map_base, [&map](const Eigen::Vector3f& p_map) {
    return !map.IsDynamicOccupied(p_map) && map.StaticState(p_map) != VoxelState::kFree;
  });
}

robotio::PointList PreprocessScan(const std::vector<robotio::DepthFrame>& frames,
                                  const robotio::Rig& rig, const DualMap& map,
                                  const Eigen::Isometry3d& T_map_base) {
  robotio::PointList merged;
  for (const robotio::DepthFrame& frame : frames) {
    if (frame.sensor_id < 0 || frame.sensor_id >= static_cast<int>(rig.kinects.size())) continue;
    const robotio::PointList points =
        robotio::DepthToBasePoints(frame, rig.kinects[static_cast<std::size_t>(frame.sensor_id)]);
    merged.insert(merged.end(), points.begin(), points.end());
  }
  return RemoveDynamicPoints(VoxelGridFilter(merged, map.config().voxel_filter_m), map,
                             T_map_base);
}

}  // namespace dynamap::mapping
