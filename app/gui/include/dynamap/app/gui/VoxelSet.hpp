// The occupied voxels of a loaded dual map, flattened once for drawing, slicing and picking
// in the Maps workspace (Qt- and VTK-free, so the logic is tested without a display).
#pragma once

#include <Eigen/Core>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "dynamap/mapping/DualOcTree.hpp"

namespace dynamap::app::gui {

// One octree node that is occupied in at least one channel. Pruned nodes stay whole (one
// bigger cube), which keeps a large uniform map cheap to draw.
struct Voxel {
  Eigen::Vector3f centre;            // m, map frame.
  float size = 0.0f;                 // m, edge of the node's cube.
  float static_probability = 0.0f;   // occupancy probability of the static channel.
  float dynamic_probability = 0.0f;  // occupancy probability of the dynamic channel.
  bool static_occupied = false;
  bool dynamic_occupied = false;
};

struct VoxelSet {
  std::vector<Voxel> voxels;
  double resolution_m = 0.0;  // m, leaf edge of the tree.
  Eigen::Vector3f min_corner = Eigen::Vector3f::Zero();  // m, bounds of all voxel cubes.
  Eigen::Vector3f max_corner = Eigen::Vector3f::Zero();
  std::size_t static_count = 0;   // nodes occupied in the static channel.
  std::size_t dynamic_count = 0;  // nodes occupied in the dynamic channel.
};

// fraction in [0, 1]; called from the extracting thread.
using ProgressCallback = std::function<void(double fraction)>;

// Every node occupied in either channel. Returns nullopt when `cancel` becomes true.
[[nodiscard]] std::optional<VoxelSet> ExtractVoxels(const mapping::DualOcTree& tree,
                                                    const std::atomic<bool>& cancel,
                                                    const ProgressCallback& progress);

enum class VoxelLayer { kStatic, kDynamic };

// What the view shows: channel toggles and a height slice on voxel centres.
struct VoxelFilter {
  bool show_static = true;
  bool show_dynamic = true;
  float z_min = -std::numeric_limits<float>::infinity();  // m, map frame.
  float z_max = std::numeric_limits<float>::infinity();   // m, map frame.
};

// A voxel occupied in both channels is drawn once, in the dynamic layer while that layer
// is shown: two coincident cubes would flicker.
[[nodiscard]] bool IsVisible(const Voxel& voxel, VoxelLayer layer, const VoxelFilter& filter);

[[nodiscard]] std::vector<std::uint32_t> VisibleIndices(const VoxelSet& set, VoxelLayer layer,
                                                        const VoxelFilter& filter);

struct VoxelPick {
  std::uint32_t index = 0;  // into VoxelSet::voxels.
  VoxelLayer layer = VoxelLayer::kStatic;
  float distance_m = 0.0f;  // along the ray to the cube's entry face.
};

// The first visible voxel cube along the ray `origin + t * direction`, t >= 0.
[[nodiscard]] std::optional<VoxelPick> PickVoxel(const VoxelSet& set, const VoxelFilter& filter,
                                                 const Eigen::Vector3f& origin,
                                                 const Eigen::Vector3f& direction);

}  // namespace dynamap::app::gui
