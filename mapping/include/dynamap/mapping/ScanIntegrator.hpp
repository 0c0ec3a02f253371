// The batched dual-map update of one scan (thesis 4.2, Algorithm 2 with Tables 4.1/4.2):
// rays → deduplicated free/hit voxels → one depth-first pass over the touched subtrees.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include <octomap/OcTreeKey.h>

#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/mapping/UpdateRules.hpp"
#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::mapping {

struct ScanStatistics {
  std::size_t rays = 0;          // Rays given.
  // End voxels traced (endpoints are discretised): the distinct ones of each thread.
  std::size_t traced_rays = 0;
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
// aggregated and pruned once, on the way back up, instead of after every voxel; the
// per-ray work shared by threads.

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
  // `threads` (at least 1) share the per-ray work of a scan: end voxels, free-space ends,
  // hits and traces, each thread in its own voxel blocks, merged with OR. The tree update
  // stays on the calling thread; the map does not depend on the number of threads.
  explicit ScanIntegrator(unsigned threads = 1);
  ~ScanIntegrator();
  ScanIntegrator(ScanIntegrator&&) noexcept;
  ScanIntegrator& operator=(ScanIntegrator&&) noexcept;

  // `rays` are in the map frame (robotio::DepthToRays with T_map_base).
  ScanStatistics Insert(DualOcTree& tree, const robotio::DepthRays& rays,
                        const UpdateRules& rules);
  // One scan seen from several origins (both Kinects of one instant): every voxel is
  // updated once, and one hit by any set counts as hit for all.
  ScanStatistics Insert(DualOcTree& tree, const std::vector<const robotio::DepthRays*>& ray_sets,
                        const UpdateRules& rules);

 private:
  struct Worker;  // One thread's voxel blocks and trace buffers (ScanIntegrator.cpp).

  unsigned threads_ = 1;
  std::vector<std::unique_ptr<Worker>> workers_;
  std::vector<octomap::OcTreeKey> end_keys_;   // Of all sets, one after the other.
  std::vector<octomap::OcTreeKey> free_keys_;  // Where each ray's free space ends.
  std::vector<std::uint8_t> end_valid_;        // Bytes: written from several threads.
  std::vector<std::uint8_t> free_valid_;
  std::vector<octomap::OcTreeKey> hit_keys_;  // Distinct hit voxels of the scan.
  std::vector<std::int32_t> order_;
};

}  // namespace dynamap::mapping
