#include "dynamap/app/gui/VoxelSet.hpp"

#include <octomap/octomap_utils.h>

#include <algorithm>
#include <cmath>

namespace dynamap::app::gui {

namespace {

// Progress is reported every this many leaves: often enough for a smooth bar, rarely enough
// that the callback (a queued post to the GUI thread) costs nothing measurable.
constexpr std::size_t kProgressStride = 65536;

// Slab test of a ray against an axis-aligned cube; the entry distance or nullopt.
std::optional<float> RayCubeEntry(const Eigen::Vector3f& origin, const Eigen::Vector3f& inv_dir,
                                  const Eigen::Vector3f& centre, float half) {
  float t_near = 0.0f;
  float t_far = std::numeric_limits<float>::infinity();
  for (int axis = 0; axis < 3; ++axis) {
    const float lo = (centre[axis] - half - origin[axis]) * inv_dir[axis];
    const float hi = (centre[axis] + half - origin[axis]) * inv_dir[axis];
    // NaN from 0 * inf (ray in the slab's plane) must not shrink the interval.
    const float t0 = std::isnan(lo) ? -std::numeric_limits<float>::infinity() : std::min(lo, hi);
    const float t1 = std::isnan(hi) ? std::numeric_limits<float>::infinity() : std::max(lo, hi);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
    if (t_near > t_far) return std::nullopt;
  }
  return t_near;
}

}  // namespace

std::optional<VoxelSet> ExtractVoxels(const mapping::DualOcTree& tree,
                                      const std::atomic<bool>& cancel,
                                      const ProgressCallback& progress) {
  VoxelSet set;
  set.resolution_m = tree.getResolution();
  const std::size_t leaf_count = std::max<std::size_t>(1, tree.getNumLeafNodes());
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::infinity());
  Eigen::Vector3f hi = -lo;
  std::size_t visited = 0;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    if (++visited % kProgressStride == 0) {
      if (cancel.load()) return std::nullopt;
      if (progress) progress(static_cast<double>(visited) / static_cast<double>(leaf_count));
    }
    const auto& node = *it;
    const bool is_static = tree.IsStaticOccupied(node);
    const bool is_dynamic = tree.IsDynamicOccupied(node);
    if (!is_static && !is_dynamic) continue;
    Voxel voxel;
    voxel.centre = Eigen::Vector3f(it.getX(), it.getY(), it.getZ());
    voxel.size = static_cast<float>(it.getSize());
    voxel.static_probability = static_cast<float>(octomap::probability(node.StaticLogOdds()));
    voxel.dynamic_probability = static_cast<float>(octomap::probability(node.DynamicLogOdds()));
    voxel.static_occupied = is_static;
    voxel.dynamic_occupied = is_dynamic;
    set.static_count += is_static ? 1 : 0;
    set.dynamic_count += is_dynamic ? 1 : 0;
    const Eigen::Vector3f half = Eigen::Vector3f::Constant(voxel.size / 2.0f);
    lo = lo.cwiseMin(voxel.centre - half);
    hi = hi.cwiseMax(voxel.centre + half);
    set.voxels.push_back(voxel);
  }
  if (cancel.load()) return std::nullopt;
  if (!set.voxels.empty()) {
    set.min_corner = lo;
    set.max_corner = hi;
  }
  if (progress) progress(1.0);
  return set;
}

bool IsVisible(const Voxel& voxel, VoxelLayer layer, const VoxelFilter& filter) {
  if (voxel.centre.z() < filter.z_min || voxel.centre.z() > filter.z_max) return false;
  if (layer == VoxelLayer::kDynamic) return filter.show_dynamic && voxel.dynamic_occupied;
  return filter.show_static && voxel.static_occupied &&
         !(filter.show_dynamic && voxel.dynamic_occupied);
}

std::vector<std::uint32_t> VisibleIndices(const VoxelSet& set, VoxelLayer layer,
                                          const VoxelFilter& filter) {
  std::vector<std::uint32_t> indices;
  for (std::size_t i = 0; i < set.voxels.size(); ++i) {
    if (IsVisible(set.voxels[i], layer, filter)) indices.push_back(static_cast<std::uint32_t>(i));
  }
  return indices;
}

std::optional<VoxelPick> PickVoxel(const VoxelSet& set, const VoxelFilter& filter,
                                   const Eigen::Vector3f& origin,
                                   const Eigen::Vector3f& direction) {
  if (direction.squaredNorm() == 0.0f) return std::nullopt;
  const Eigen::Vector3f dir = direction.normalized();
  const Eigen::Vector3f inv_dir = dir.cwiseInverse();
  std::optional<VoxelPick> best;
  for (std::size_t i = 0; i < set.voxels.size(); ++i) {
    const Voxel& voxel = set.voxels[i];
    const bool as_dynamic = IsVisible(voxel, VoxelLayer::kDynamic, filter);
    if (!as_dynamic && !IsVisible(voxel, VoxelLayer::kStatic, filter)) continue;
    const auto t = RayCubeEntry(origin, inv_dir, voxel.centre, voxel.size / 2.0f);
    if (!t || (best && *t >= best->distance_m)) continue;
    best = VoxelPick{static_cast<std::uint32_t>(i),
                     as_dynamic ? VoxelLayer::kDynamic : VoxelLayer::kStatic, *t};
  }
  return best;
}

}  // namespace dynamap::app::gui
