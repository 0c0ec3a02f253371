// The batched dual-map update of one scan (thesis 4.2, Algorithm 2 with Tables 4.1/4.2):
// rays → deduplicated free/hit voxels → one depth-first pass over the touched subtrees.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include <octomap/OcTreeKey.h>

#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/mapping/UpdateRules.hpp"
#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::mapping {

struct ScanStatistics {
  std::size_t rays = 0;          // Rays given.
  std::size_t traced_rays = 0;   // Distinct end voxels traced (endpoints are discretised).
  std::size_t hit_voxels = 0;    // Voxels observed occupied.
  std::size_t free_voxels = 0;   // Voxels observed free (and not hit).
};

// Rules of one scan: each ray's end point is discretised to its voxel and observed
// occupied when the ray hit. Free space: the voxels from the origin to the centre of the
// voxel holding FreeSpaceEnd (excluded) are observed free, except voxels hit in this scan
// (a voxel both hit and traversed counts as hit) and, with `surface_band`, their 26
// neighbours. Every voxel is updated once per scan with ApplyObservation.
//
// Why it is fast: per-scan deduplication in 8x8x8-voxel bit blocks (no hashing per ray
// step), blocks visited in Morton order so each tree path is walked once, and inner nodes
// aggregated and pruned once, on the way back up, instead of after every voxel.
// Where ray `i` stops observing free space: its end point, or with a known incidence, the
// point surface_margin_m / max(incidence_cos, min_incidence_cos) before the surface it
// measured (where the ray comes within surface_margin_m of the surface plane); for a ray
// cut at max range that point when it lies before the cut end (the floor just beyond max
// range is grazed by the ray's last decimetres). With `alongside_range_m`, no farther than
// the margin before the nearest surface beside the ray, unless the ray ends below the floor
// layers (it passed over a hole's edge). nullopt when the margin is longer than the ray.
[[nodiscard]] std::optional<Eigen::Vector3f> FreeSpaceEnd(const robotio::DepthRays& rays,
                                                          std::size_t i, const UpdateRules& rules);

// Key (z) of the voxel layer just above the floor plane z = 0 (MappingConfig::floor_plane).
[[nodiscard]] octomap::key_type FloorLayerKey(const DualOcTree& tree);

class ScanIntegrator {
 public:
  // `rays` are in the map frame (robotio::DepthToRays with T_map_base).
  ScanStatistics Insert(DualOcTree& tree, const robotio::DepthRays& rays,
                        const UpdateRules& rules);
  // One scan seen from several origins (both Kinects of one instant): every voxel is
  // updated once, and one hit by any set counts as hit for all.
  ScanStatistics Insert(DualOcTree& tree, const std::vector<const robotio::DepthRays*>& ray_sets,
                        const UpdateRules& rules);

 private:
  struct Block {
    std::uint64_t morton = 0;     // Block coordinates interleaved: depth-first tree order.
    std::uint16_t coords[3] = {0, 0, 0};  // key >> 3 per axis.
    std::uint64_t free[8] = {};   // Bit (Morton index within block) per voxel.
    std::uint64_t hit[8] = {};
    std::uint64_t end[8] = {};    // End voxel already queued for tracing.
  };

  Block& BlockFor(const octomap::OcTreeKey& key);
  Block* FindBlock(const octomap::OcTreeKey& key);  // nullptr when the scan has no such block.
  // Every hit's 26 neighbours, but above a hit in `floor_layer` (floor_plane) none.
  void ClearSurfaceBand(std::optional<octomap::key_type> floor_layer);
  void PrepareIndex(const octomap::OcTreeKey& min_key, const octomap::OcTreeKey& max_key);
  void UpdateTree(DualOcTree& tree, const UpdateRules& rules, ScanStatistics* stats);

  std::vector<Block> blocks_;
  std::vector<std::int32_t> dense_index_;  // Block slot per block cell of the scan's box.
  std::unordered_map<std::uint64_t, std::int32_t> sparse_index_;  // When the box is huge.
  bool use_dense_ = true;
  std::uint16_t box_min_[3] = {0, 0, 0};
  std::uint32_t box_dims_[3] = {0, 0, 0};
  std::int32_t last_slot_ = -1;
  std::uint64_t last_block_id_ = ~0ull;
  std::vector<octomap::OcTreeKey> end_keys_;  // Of all sets, one after the other.
  std::vector<bool> end_valid_;
  std::vector<octomap::OcTreeKey> unique_ends_;
  std::vector<octomap::OcTreeKey> hit_keys_;  // Distinct hit voxels of the scan.
  std::vector<std::int32_t> order_;
  octomap::KeyRay key_ray_;
};

}  // namespace dynamap::mapping
