// The dual static/dynamic map as SLAM and the CLI use it (thesis 4.2-4.3, Algorithm 4
// line 11): insert scans from a pose, ask whether a point is static or dynamic.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <vector>

#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/mapping/MappingConfig.hpp"
#include "dynamap/mapping/ScanIntegrator.hpp"
#include "dynamap/mapping/UpdateRules.hpp"
#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::mapping {

// State of one voxel in one channel.
enum class VoxelState { kUnknown, kFree, kOccupied };

class DualMap {
 public:
  explicit DualMap(const MappingConfig& config);
  // Takes over a loaded tree (MapFiles); the config's resolution is replaced by the tree's.
  DualMap(std::unique_ptr<DualOcTree> tree, const MappingConfig& config);

  // The rays of a depth frame taken at base pose T_map_base as this map inserts them: max
  // range the smaller of the mount's and the config's, edge clearance from the config.
  [[nodiscard]] robotio::DepthRays RaysOf(const robotio::DepthFrame& frame,
                                          const robotio::KinectMount& mount,
                                          const Eigen::Isometry3d& T_map_base) const;
  // One scan already as rays in the map frame (RaysOf, or robotio::DepthToRays).
  ScanStatistics InsertRays(const robotio::DepthRays& rays);
  // One scan seen from several origins: both Kinects of one instant, each voxel updated
  // once (ScanIntegrator). Rays in the map frame.
  ScanStatistics InsertScan(const std::vector<robotio::DepthRays>& ray_sets);
  // The frames of one instant, frames[i] taken by mounts[i] at base pose T_map_base[i];
  // max range as for InsertDepthFrame.
  ScanStatistics InsertDepthFrames(const std::vector<const robotio::DepthFrame*>& frames,
                                   const std::vector<robotio::KinectMount>& mounts,
                                   const std::vector<Eigen::Isometry3d>& T_map_base);
  // One depth frame taken at base pose T_map_base; rays beyond the config's max range
  // clear free space up to it (the mount's own range limits apply first).
  ScanStatistics InsertDepthFrame(const robotio::DepthFrame& frame,
                                  const robotio::KinectMount& mount,
                                  const Eigen::Isometry3d& T_map_base);
  // Points in the map frame measured from `origin_map`; points farther than max range
  // clear up to it and set no hit (octomap::OcTree::insertPointCloud's rule).
  ScanStatistics InsertPointCloud(const robotio::PointList& points_map,
                                  const Eigen::Vector3f& origin_map);

  [[nodiscard]] VoxelState StaticState(const Eigen::Vector3f& p_map) const;
  [[nodiscard]] VoxelState DynamicState(const Eigen::Vector3f& p_map) const;
  [[nodiscard]] bool IsDynamicOccupied(const Eigen::Vector3f& p_map) const {
    return DynamicState(p_map) == VoxelState::kOccupied;
  }
  [[nodiscard]] bool IsStaticOccupied(const Eigen::Vector3f& p_map) const {
    return StaticState(p_map) == VoxelState::kOccupied;
  }

  [[nodiscard]] const DualOcTree& tree() const { return *tree_; }
  [[nodiscard]] DualOcTree& tree() { return *tree_; }
  [[nodiscard]] const MappingConfig& config() const { return config_; }
  [[nodiscard]] const UpdateRules& rules() const { return rules_; }

 private:
  [[nodiscard]] const DualOcTreeNode* Find(const Eigen::Vector3f& p_map) const;
  void ApplyConfigToTree();

  MappingConfig config_;
  UpdateRules rules_;
  std::unique_ptr<DualOcTree> tree_;
  ScanIntegrator integrator_;
};

// Rays of a point cloud with max-range cutting: a point farther than `max_range_m` from
// the origin becomes a ray cut at that distance with no hit.
[[nodiscard]] robotio::DepthRays RaysFromPoints(const robotio::PointList& points_map,
                                                const Eigen::Vector3f& origin_map,
                                                double max_range_m);

}  // namespace dynamap::mapping
