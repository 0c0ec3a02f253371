#include "dynamap/mapping/ScanIntegrator.hpp"

#include <algorithm>

namespace dynamap::mapping {
namespace {

constexpr unsigned kTreeDepth = 16;
constexpr unsigned kBlockDepth = kTreeDepth - 3;  // Depth of the 8x8x8 block's subtree root.
constexpr std::size_t kMaxDenseCells = std::size_t{1} << 22;

// Spreads the 3 low bits of v to bits 0, 3, 6.
constexpr std::uint32_t Spread3(std::uint32_t v) {
  return (v & 1u) | ((v & 2u) << 2) | ((v & 4u) << 4);
}

// Morton index of a voxel inside its block; the top 3 bits are the child index at depth
// 14, as octomap::computeChildIdx orders them (x = 1, y = 2, z = 4).
inline std::uint32_t InBlockIndex(const octomap::OcTreeKey& key) {
  return Spread3(key[0] & 7u) | (Spread3(key[1] & 7u) << 1) | (Spread3(key[2] & 7u) << 2);
}

std::uint64_t Interleave13(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  std::uint64_t code = 0;
  for (int bit = 12; bit >= 0; --bit) {
    code = (code << 3) | ((x >> bit) & 1u) | (((y >> bit) & 1u) << 1) | (((z >> bit) & 1u) << 2);
  }
  return code;
}

// Child `index` of `node`, created when absent. A childless node that existed before this
// scan is a pruned inner node standing for eight equal children: it is expanded so that
// only the observed child changes. `*is_new` says whether the child was never observed.
DualOcTreeNode* Descend(DualOcTree& tree, DualOcTreeNode* node, bool node_is_new,
                        unsigned index, bool* is_new) {
  if (tree.nodeChildExists(node, index)) {
    *is_new = false;
    return tree.getNodeChild(node, index);
  }
  if (!node_is_new && !tree.nodeHasChildren(node)) {
    tree.expandNode(node);
    *is_new = false;
    return tree.getNodeChild(node, index);
  }
  *is_new = true;
  return tree.createNodeChild(node, index);
}

// Once all children of an inner node are final: collapse eight equal leaves, otherwise
// take the children's maxima in both channels.
void Finish(DualOcTree& tree, DualOcTreeNode* node, bool allow_prune) {
  if (!tree.nodeHasChildren(node)) return;
  if (allow_prune && tree.pruneNode(node)) return;
  node->updateOccupancyChildren();
}

bool AnyBit(const std::uint64_t (&a)[8], const std::uint64_t (&b)[8]) {
  std::uint64_t any = 0;
  for (int w = 0; w < 8; ++w) any |= a[w] | b[w];
  return any != 0;
}

}  // namespace

void ScanIntegrator::PrepareIndex(const octomap::OcTreeKey& min_key,
                                  const octomap::OcTreeKey& max_key) {
  blocks_.clear();
  last_slot_ = -1;
  last_block_id_ = ~0ull;
  std::size_t cells = 1;
  for (int a = 0; a < 3; ++a) {
    box_min_[a] = static_cast<std::uint16_t>(min_key[a] >> 3);
    box_dims_[a] = static_cast<std::uint32_t>((max_key[a] >> 3) - box_min_[a] + 1);
    cells *= box_dims_[a];
  }
  use_dense_ = cells <= kMaxDenseCells;
  if (use_dense_) {
    dense_index_.assign(cells, -1);
  } else {
    sparse_index_.clear();
  }
}

ScanIntegrator::Block& ScanIntegrator::BlockFor(const octomap::OcTreeKey& key) {
  const std::uint32_t bx = key[0] >> 3, by = key[1] >> 3, bz = key[2] >> 3;
  const std::uint64_t id = (std::uint64_t{bx} << 32) | (std::uint64_t{by} << 16) | bz;
  if (id == last_block_id_) return blocks_[static_cast<std::size_t>(last_slot_)];
  std::int32_t* slot = nullptr;
  if (use_dense_) {
    const std::size_t cell =
        (static_cast<std::size_t>(bz - box_min_[2]) * box_dims_[1] + (by - box_min_[1])) *
            box_dims_[0] +
        (bx - box_min_[0]);
    slot = &dense_index_[cell];
  } else {
    slot = &sparse_index_.try_emplace(id, -1).first->second;
  }
  if (*slot < 0) {
    *slot = static_cast<std::int32_t>(blocks_.size());
    Block& block = blocks_.emplace_back();
    block.coords[0] = static_cast<std::uint16_t>(bx);
    block.coords[1] = static_cast<std::uint16_t>(by);
    block.coords[2] = static_cast<std::uint16_t>(bz);
    block.morton = Interleave13(bx, by, bz);
  }
  last_block_id_ = id;
  last_slot_ = *slot;
  return blocks_[static_cast<std::size_t>(*slot)];
}

ScanStatistics ScanIntegrator::Insert(DualOcTree& tree, const robotio::DepthRays& rays,
                                      const UpdateRules& rules) {
  return Insert(tree, std::vector<const robotio::DepthRays*>{&rays}, rules);
}

ScanStatistics ScanIntegrator::Insert(DualOcTree& tree,
                                      const std::vector<const robotio::DepthRays*>& ray_sets,
                                      const UpdateRules& rules) {
  ScanStatistics stats;
  // Origins and end voxels of every set, and the box that holds every ray (a ray's voxels
  // lie between its ends). A set whose origin lies outside the tree is left out.
  std::vector<bool> usable(ray_sets.size(), false);
  std::vector<std::size_t> first_end(ray_sets.size(), 0);  // Of each set in end_keys_.
  std::size_t total = 0;
  bool any = false;
  octomap::OcTreeKey min_key, max_key;
  for (std::size_t s = 0; s < ray_sets.size(); ++s) {
    const robotio::DepthRays& rays = *ray_sets[s];
    stats.rays += rays.ends.size();
    first_end[s] = total;
    const Eigen::Vector3f& o = rays.origin;
    octomap::OcTreeKey origin_key;
    if (!tree.coordToKeyChecked(octomap::point3d(o.x(), o.y(), o.z()), origin_key)) continue;
    usable[s] = true;
    total += rays.ends.size();
    if (!any) min_key = max_key = origin_key;
    any = true;
    for (int a = 0; a < 3; ++a) {
      min_key[a] = std::min(min_key[a], origin_key[a]);
      max_key[a] = std::max(max_key[a], origin_key[a]);
    }
  }
  if (!any) return stats;
  end_keys_.resize(total);
  end_valid_.assign(total, false);
  for (std::size_t s = 0; s < ray_sets.size(); ++s) {
    if (!usable[s]) continue;
    const robotio::DepthRays& rays = *ray_sets[s];
    for (std::size_t i = 0; i < rays.ends.size(); ++i) {
      const Eigen::Vector3f& p = rays.ends[i];
      octomap::OcTreeKey& key = end_keys_[first_end[s] + i];
      if (!tree.coordToKeyChecked(octomap::point3d(p.x(), p.y(), p.z()), key)) continue;
      end_valid_[first_end[s] + i] = true;
      for (int a = 0; a < 3; ++a) {
        min_key[a] = std::min(min_key[a], key[a]);
        max_key[a] = std::max(max_key[a], key[a]);
      }
    }
  }
  PrepareIndex(min_key, max_key);

  hit_keys_.clear();
  for (std::size_t s = 0; s < ray_sets.size(); ++s) {
    if (!usable[s]) continue;
    const robotio::DepthRays& rays = *ray_sets[s];
    const octomap::point3d origin(rays.origin.x(), rays.origin.y(), rays.origin.z());
    // Hits, and the distinct free-space end voxels of this origin.
    unique_ends_.clear();
    for (std::size_t i = 0; i < rays.ends.size(); ++i) {
      if (!end_valid_[first_end[s] + i]) continue;
      const octomap::OcTreeKey& end_key = end_keys_[first_end[s] + i];
      if (rays.hit[i]) {
        Block& block = BlockFor(end_key);
        const std::uint32_t bit = InBlockIndex(end_key);
        const std::uint64_t mask = std::uint64_t{1} << (bit & 63u);
        if ((block.hit[bit >> 6] & mask) == 0) hit_keys_.push_back(end_key);
        block.hit[bit >> 6] |= mask;
      }
      const std::optional<Eigen::Vector3f> free_end = FreeSpaceEnd(rays, i, rules);
      if (!free_end) continue;
      octomap::OcTreeKey key = end_key;
      if (*free_end != rays.ends[i] &&
          !tree.coordToKeyChecked(octomap::point3d(free_end->x(), free_end->y(), free_end->z()),
                                  key)) {
        continue;
      }
      Block& block = BlockFor(key);
      const std::uint32_t bit = InBlockIndex(key);
      const std::uint64_t mask = std::uint64_t{1} << (bit & 63u);
      if ((block.end[bit >> 6] & mask) == 0) {
        block.end[bit >> 6] |= mask;
        unique_ends_.push_back(key);
      }
    }

    // Free space: one trace per distinct free-space end voxel, to its centre (OctoMap's
    // discretise; the free end of a hit with a margin lies between the origin and the hit).
    stats.traced_rays += unique_ends_.size();
    for (const octomap::OcTreeKey& end_key : unique_ends_) {
      Block& end_block = BlockFor(end_key);
      const std::uint32_t end_bit = InBlockIndex(end_key);
      end_block.end[end_bit >> 6] &= ~(std::uint64_t{1} << (end_bit & 63u));  // For the next origin.
      if (!tree.computeRayKeys(origin, tree.keyToCoord(end_key), key_ray_)) continue;
      for (const octomap::OcTreeKey& key : key_ray_) {
        Block& block = BlockFor(key);
        const std::uint32_t bit = InBlockIndex(key);
        block.free[bit >> 6] |= std::uint64_t{1} << (bit & 63u);
      }
    }
  }
  if (rules.surface_band) {
    ClearSurfaceBand(rules.floor_plane ? std::optional<octomap::key_type>(FloorLayerKey(tree))
                                       : std::nullopt);
  }
  UpdateTree(tree, rules, &stats);
  return stats;
}

ScanIntegrator::Block* ScanIntegrator::FindBlock(const octomap::OcTreeKey& key) {
  const std::uint32_t bx = key[0] >> 3, by = key[1] >> 3, bz = key[2] >> 3;
  std::int32_t slot = -1;
  if (use_dense_) {
    if (bx < box_min_[0] || by < box_min_[1] || bz < box_min_[2]) return nullptr;
    const std::uint32_t cx = bx - box_min_[0], cy = by - box_min_[1], cz = bz - box_min_[2];
    if (cx >= box_dims_[0] || cy >= box_dims_[1] || cz >= box_dims_[2]) return nullptr;
    slot = dense_index_[(static_cast<std::size_t>(cz) * box_dims_[1] + cy) * box_dims_[0] + cx];
  } else {
    const auto it = sparse_index_.find((std::uint64_t{bx} << 32) | (std::uint64_t{by} << 16) | bz);
    if (it != sparse_index_.end()) slot = it->second;
  }
  return slot < 0 ? nullptr : &blocks_[static_cast<std::size_t>(slot)];
}

octomap::key_type FloorLayerKey(const DualOcTree& tree) {
  return tree.coordToKey(0.5 * tree.getResolution());
}

void ScanIntegrator::ClearSurfaceBand(std::optional<octomap::key_type> floor_layer) {
  for (const octomap::OcTreeKey& key : hit_keys_) {
    const int top = floor_layer && key[2] == *floor_layer ? 0 : 1;  // Nothing above the floor.
    for (int dz = -1; dz <= top; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const octomap::OcTreeKey n(static_cast<octomap::key_type>(key[0] + dx),
                                     static_cast<octomap::key_type>(key[1] + dy),
                                     static_cast<octomap::key_type>(key[2] + dz));
          Block* block = FindBlock(n);
          if (block == nullptr) continue;  // Nothing of the scan there.
          const std::uint32_t bit = InBlockIndex(n);
          block->free[bit >> 6] &= ~(std::uint64_t{1} << (bit & 63u));
        }
      }
    }
  }
}

std::optional<Eigen::Vector3f> FreeSpaceEnd(const robotio::DepthRays& rays, std::size_t i,
                                            const UpdateRules& rules) {
  const Eigen::Vector3f& end = rays.ends[i];
  const Eigen::Vector3f ray = end - rays.origin;
  const float length = ray.norm();
  float free_length = length;
  if (rules.floor_plane && rays.hit[i] && end.z() >= -rules.resolution_m &&
      end.z() < rules.resolution_m && rays.origin.z() > 1.5f * rules.resolution_m) {
    // A floor hit from above: free down to the middle of the layer above the floor layers.
    const float above = 1.5f * rules.resolution_m;
    const float z0 = rays.origin.z();
    free_length = length * ((z0 - above) / (z0 - end.z()));
  } else if (rules.surface_margin_m > 0.0f && !rays.incidence_cos.empty()) {
    // A ray cut at max range knows its surface only when it carries the surface's range.
    const float surface =
        rays.hit[i] ? length : (rays.surface_range_m.empty() ? 0.0f : rays.surface_range_m[i]);
    if (surface > 0.0f) {
      free_length = surface - rules.surface_margin_m /
                                  std::max(rays.incidence_cos[i], rules.min_incidence_cos);
    }
  }
  // A ray ending below the floor layers passed over a hole's edge (a stair pit): the floor
  // beside it is that edge, and the free space it shows below the floor is what marks the
  // hole for the planner, so the depth-edge rule leaves it alone.
  const bool into_hole = rules.floor_plane && end.z() < -rules.resolution_m;
  if (!rays.alongside_range_m.empty() && !into_hole) {
    // Beside a nearer surface (a depth edge): no free space from where the ray passes it.
    free_length = std::min(free_length, rays.alongside_range_m[i] - rules.surface_margin_m);
  }
  if (free_length <= 0.0f) return std::nullopt;
  if (free_length >= length) return end;  // The margin lies beyond the cut end.
  return rays.origin + ray * (free_length / length);
}

void ScanIntegrator::UpdateTree(DualOcTree& tree, const UpdateRules& rules,
                                ScanStatistics* stats) {
  if (blocks_.empty()) return;
  order_.resize(blocks_.size());
  for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = static_cast<std::int32_t>(i);
  std::sort(order_.begin(), order_.end(), [this](std::int32_t a, std::int32_t b) {
    return blocks_[static_cast<std::size_t>(a)].morton < blocks_[static_cast<std::size_t>(b)].morton;
  });

  // path[d] is the node at depth d on the way to the current block.
  DualOcTreeNode* path[kBlockDepth + 1] = {};
  bool path_new[kBlockDepth + 1] = {};
  path_new[0] = tree.MutableRoot() == nullptr;
  path[0] = tree.CreateRoot();
  const Block* previous = nullptr;

  for (const std::int32_t slot : order_) {
    const Block& block = blocks_[static_cast<std::size_t>(slot)];
    // A block holding only the end of a ray cut at max range (no hit, not traversed) has
    // nothing to update; descending into it would leave a childless node with the prior,
    // which reads as a pruned, occupied 8x8x8 cube.
    if (!AnyBit(block.free, block.hit)) continue;
    unsigned common = 0;  // Deepest depth whose node the previous block shares.
    if (previous != nullptr) {
      const std::uint32_t diff = (block.coords[0] ^ previous->coords[0]) |
                                 (block.coords[1] ^ previous->coords[1]) |
                                 (block.coords[2] ^ previous->coords[2]);
      int highest = 12;
      while (highest > 0 && ((diff >> highest) & 1u) == 0) --highest;
      common = static_cast<unsigned>(12 - highest);
      for (unsigned d = kBlockDepth; d > common; --d) Finish(tree, path[d], true);
    }
    for (unsigned d = common; d < kBlockDepth; ++d) {
      const unsigned bit = 12 - d;
      const unsigned index = ((block.coords[0] >> bit) & 1u) | (((block.coords[1] >> bit) & 1u) << 1) |
                             (((block.coords[2] >> bit) & 1u) << 2);
      path[d + 1] = Descend(tree, path[d], path_new[d], index, &path_new[d + 1]);
    }

    DualOcTreeNode* block_node = path[kBlockDepth];
    for (unsigned c1 = 0; c1 < 8; ++c1) {
      const std::uint64_t observed = block.free[c1] | block.hit[c1];
      if (observed == 0) continue;
      bool new14 = false;
      DualOcTreeNode* n14 = Descend(tree, block_node, path_new[kBlockDepth], c1, &new14);
      for (unsigned c2 = 0; c2 < 8; ++c2) {
        const unsigned byte = static_cast<unsigned>((observed >> (c2 * 8)) & 0xffu);
        if (byte == 0) continue;
        bool new15 = false;
        DualOcTreeNode* n15 = Descend(tree, n14, new14, c2, &new15);
        for (unsigned c3 = 0; c3 < 8; ++c3) {
          if (((byte >> c3) & 1u) == 0) continue;
          bool leaf_new = false;
          DualOcTreeNode* leaf = Descend(tree, n15, new15, c3, &leaf_new);
          const bool hit = ((block.hit[c1] >> (c2 * 8 + c3)) & 1u) != 0;
          const DualLogOdds next = ApplyObservation(
              {leaf->StaticLogOdds(), leaf->DynamicLogOdds()}, !leaf_new,
              hit ? Observation::kOccupied : Observation::kFree, rules);
          leaf->SetStaticLogOdds(next.static_log_odds);
          leaf->SetDynamicLogOdds(next.dynamic_log_odds);
          ++(hit ? stats->hit_voxels : stats->free_voxels);
        }
        Finish(tree, n15, true);
      }
      Finish(tree, n14, true);
    }
    previous = &block;
  }
  // The root is never pruned (OctoMap keeps it too).
  for (unsigned d = kBlockDepth; d > 0; --d) Finish(tree, path[d], true);
  Finish(tree, path[0], false);
}

}  // namespace dynamap::mapping
