#include "dynamap/mapping/DualMap.hpp"

#include <octomap/octomap_utils.h>

#include <algorithm>
#include <cmath>

namespace dynamap::mapping {

DualMap::DualMap(const MappingConfig& config)
    : config_(config),
      rules_(UpdateRules::FromConfig(config)),
      tree_(std::make_unique<DualOcTree>(config.resolution_m)),
      integrator_(static_cast<unsigned>(config.insert_threads)) {
  ApplyConfigToTree();
}

DualMap::DualMap(std::unique_ptr<DualOcTree> tree, const MappingConfig& config)
    : config_(config),
      rules_(UpdateRules::FromConfig(config)),
      tree_(std::move(tree)),
      integrator_(static_cast<unsigned>(config.insert_threads)) {
  config_.resolution_m = tree_->getResolution();
  rules_ = UpdateRules::FromConfig(config_);  // The surface margin is in voxels of this tree.
  ApplyConfigToTree();
}

void DualMap::ApplyConfigToTree() {
  tree_->setOccupancyThres(config_.occupancy_threshold);
  tree_->setClampingThresMin(config_.clamp_min);
  tree_->setClampingThresMax(config_.clamp_max);
  tree_->setProbHit(config_.prob_high);
  tree_->setProbMiss(config_.prob_low);
}

ScanStatistics DualMap::InsertRays(const robotio::DepthRays& rays) {
  return integrator_.Insert(*tree_, rays, rules_);
}

ScanStatistics DualMap::InsertScan(const std::vector<robotio::DepthRays>& ray_sets) {
  std::vector<const robotio::DepthRays*> sets;
  sets.reserve(ray_sets.size());
  for (const robotio::DepthRays& rays : ray_sets) sets.push_back(&rays);
  return integrator_.Insert(*tree_, sets, rules_);
}

ScanStatistics DualMap::InsertDepthFrames(const std::vector<const robotio::DepthFrame*>& frames,
                                          const std::vector<robotio::KinectMount>& mounts,
                                          const std::vector<Eigen::Isometry3d>& T_map_base) {
  std::vector<robotio::DepthRays> ray_sets;
  ray_sets.reserve(frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    ray_sets.push_back(RaysOf(*frames[i], mounts[i], T_map_base[i]));
  }
  return InsertScan(ray_sets);
}

robotio::DepthRays DualMap::RaysOf(const robotio::DepthFrame& frame,
                                   const robotio::KinectMount& mount,
                                   const Eigen::Isometry3d& T_map_base) const {
  robotio::KinectMount limited = mount;
  limited.max_range_m = std::min(mount.max_range_m, config_.max_range_m);
  robotio::EdgeClearance edges;
  edges.lateral_m = config_.edge_clearance_voxels * config_.resolution_m;
  // The gap reach in pixels of this image (the angle at its focal length).
  edges.grazing_gap_px = static_cast<int>(std::lround(
      std::tan(config_.grazing_gap_deg * M_PI / 180.0) *
      std::min(frame.intrinsics.fx, frame.intrinsics.fy)));
  // The floor layers (floor_plane) seed no gaps: far off, the floor is grazing everywhere.
  if (config_.floor_plane) edges.gap_min_height_m = config_.resolution_m;
  edges.side_depth_m = config_.unseen_side_depth_m;
  return robotio::DepthToRays(frame, limited, T_map_base, 1, edges);
}

ScanStatistics DualMap::InsertDepthFrame(const robotio::DepthFrame& frame,
                                         const robotio::KinectMount& mount,
                                         const Eigen::Isometry3d& T_map_base) {
  return InsertRays(RaysOf(frame, mount, T_map_base));
}

ScanStatistics DualMap::InsertPointCloud(const robotio::PointList& points_map,
                                         const Eigen::Vector3f& origin_map) {
  return InsertRays(RaysFromPoints(points_map, origin_map, config_.max_range_m));
}

const DualOcTreeNode* DualMap::Find(const Eigen::Vector3f& p_map) const {
  octomap::OcTreeKey key;
  if (!tree_->coordToKeyChecked(octomap::point3d(p_map.x(), p_map.y(), p_map.z()), key)) {
    return nullptr;
  }
  return tree_->search(key);  // A pruned ancestor answers for its whole cube.
}

VoxelState DualMap::StaticState(const Eigen::Vector3f& p_map) const {
  const DualOcTreeNode* node = Find(p_map);
  if (node == nullptr) return VoxelState::kUnknown;
  // The same three-way split the update rules use (free only with enough free evidence).
  switch (ClassifyStatic(node->getValue(), rules_)) {
    case StaticState::kOccupied: return VoxelState::kOccupied;
    case StaticState::kFree: return VoxelState::kFree;
    case StaticState::kUnknown: break;
  }
  return VoxelState::kUnknown;
}

VoxelState DualMap::DynamicState(const Eigen::Vector3f& p_map) const {
  const DualOcTreeNode* node = Find(p_map);
  if (node == nullptr) return VoxelState::kUnknown;
  return tree_->IsDynamicOccupied(*node) ? VoxelState::kOccupied : VoxelState::kFree;
}

robotio::DepthRays RaysFromPoints(const robotio::PointList& points_map,
                                  const Eigen::Vector3f& origin_map, double max_range_m) {
  robotio::DepthRays rays;
  rays.origin = origin_map;
  rays.ends.reserve(points_map.size());
  rays.hit.reserve(points_map.size());
  const float max_range = static_cast<float>(max_range_m);
  for (const Eigen::Vector3f& p : points_map) {
    if (!p.allFinite()) continue;
    const Eigen::Vector3f d = p - origin_map;
    const float length = d.norm();
    if (length <= max_range) {
      rays.ends.push_back(p);
      rays.hit.push_back(true);
    } else {
      rays.ends.push_back(origin_map + d * (max_range / length));
      rays.hit.push_back(false);
    }
  }
  return rays;
}

}  // namespace dynamap::mapping
