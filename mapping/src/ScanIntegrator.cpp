#include "dynamap/mapping/ScanIntegrator.hpp"

#include <algorithm>
#include <thread>

#include "ScanBlocks.hpp"

namespace dynamap::mapping {
namespace {

constexpr unsigned kTreeDepth = 16;
constexpr unsigned kBlockDepth = kTreeDepth - 3;  // Depth of the 8x8x8 block's subtree root.
// Below this many rays per thread a second thread costs more than it saves.
constexpr std::size_t kMinRaysPerThread = 20000;
// Rays are dealt to the threads in runs of this many (PartOf).
constexpr std::size_t kRaysPerRun = 8192;

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

// Every hit's 26 neighbours, but above a hit in `floor_layer` (floor_plane) none.
void ClearSurfaceBand(ScanBlocks& blocks, const std::vector<octomap::OcTreeKey>& hit_keys,
                      std::optional<octomap::key_type> floor_layer) {
  for (const octomap::OcTreeKey& key : hit_keys) {
    const int top = floor_layer && key[2] == *floor_layer ? 0 : 1;  // Nothing above the floor.
    for (int dz = -1; dz <= top; ++dz) {
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const octomap::OcTreeKey n(static_cast<octomap::key_type>(key[0] + dx),
                                     static_cast<octomap::key_type>(key[1] + dy),
                                     static_cast<octomap::key_type>(key[2] + dz));
          ScanBlock* block = blocks.FindBlock(n);
          if (block != nullptr) ClearBit(block->free, n);  // nullptr: nothing of the scan there.
        }
      }
    }
  }
}

// Applies each observed voxel of `blocks` once, walking the blocks in Morton (depth-first)
// order; `order` is scratch space.
void UpdateTree(DualOcTree& tree, const std::vector<ScanBlock>& blocks, const UpdateRules& rules,
                std::vector<std::int32_t>& order, ScanStatistics* stats) {
  if (blocks.empty()) return;
  order.resize(blocks.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::int32_t>(i);
  std::sort(order.begin(), order.end(), [&blocks](std::int32_t a, std::int32_t b) {
    return blocks[static_cast<std::size_t>(a)].morton < blocks[static_cast<std::size_t>(b)].morton;
  });

  // path[d] is the node at depth d on the way to the current block.
  DualOcTreeNode* path[kBlockDepth + 1] = {};
  bool path_new[kBlockDepth + 1] = {};
  path_new[0] = tree.MutableRoot() == nullptr;
  path[0] = tree.CreateRoot();
  const ScanBlock* previous = nullptr;

  for (const std::int32_t slot : order) {
    const ScanBlock& block = blocks[static_cast<std::size_t>(slot)];
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


// Rays [begin, end) of ray set `set`.
struct Span {
  std::size_t set = 0, begin = 0, end = 0;
};

// Part `part` of `parts` of all rays (sets one after the other, set s starting at
// first_ray[s]), as spans of their sets: every parts-th run of kRaysPerRun rays, so that
// each part gets rays from all of the image (near floor, far walls) alike.
std::vector<Span> PartOf(const std::vector<Span>& sets, const std::vector<std::size_t>& first_ray,
                         std::size_t total, unsigned part, unsigned parts) {
  std::vector<Span> spans;
  for (std::size_t first = part * kRaysPerRun; first < total; first += parts * kRaysPerRun) {
    const std::size_t last = std::min(total, first + kRaysPerRun);
    for (const Span& set : sets) {
      const std::size_t offset = first_ray[set.set];
      const std::size_t b = std::max(first, offset), e = std::min(last, offset + set.end);
      if (b < e) spans.push_back({set.set, b - offset, e - offset});
    }
  }
  return spans;
}

// Runs work(part) for part = 0 .. parts-1, part 0 on the calling thread.
template <typename Work>
void RunParts(unsigned parts, const Work& work) {
  std::vector<std::thread> helpers;
  for (unsigned part = 1; part < parts; ++part) helpers.emplace_back(work, part);
  work(0);
  for (std::thread& helper : helpers) helper.join();
}

}  // namespace

struct ScanIntegrator::Worker {
  ScanBlocks blocks;
  std::vector<octomap::OcTreeKey> unique_ends;
  octomap::KeyRay key_ray;
  std::size_t traced = 0;
  octomap::OcTreeKey min_key, max_key;  // Of the rays' keys (own copies: no shared lines).
};

ScanIntegrator::ScanIntegrator(unsigned threads) : threads_(std::max(1u, threads)) {
  for (unsigned t = 0; t < threads_; ++t) workers_.push_back(std::make_unique<Worker>());
}
ScanIntegrator::~ScanIntegrator() = default;
ScanIntegrator::ScanIntegrator(ScanIntegrator&&) noexcept = default;
ScanIntegrator& ScanIntegrator::operator=(ScanIntegrator&&) noexcept = default;

ScanStatistics ScanIntegrator::Insert(DualOcTree& tree, const robotio::DepthRays& rays,
                                      const UpdateRules& rules) {
  return Insert(tree, std::vector<const robotio::DepthRays*>{&rays}, rules);
}

ScanStatistics ScanIntegrator::Insert(DualOcTree& tree,
                                      const std::vector<const robotio::DepthRays*>& ray_sets,
                                      const UpdateRules& rules) {
  ScanStatistics stats;
  // Origins, and the box that holds every ray (a ray's voxels lie between its ends). A set
  // whose origin lies outside the tree is left out.
  std::vector<Span> sets;
  std::vector<std::size_t> first_ray(ray_sets.size(), 0);  // Of each set in end_keys_.
  std::vector<octomap::point3d> origins(ray_sets.size());
  std::size_t total = 0;
  octomap::OcTreeKey min_key, max_key;
  for (std::size_t s = 0; s < ray_sets.size(); ++s) {
    const robotio::DepthRays& rays = *ray_sets[s];
    stats.rays += rays.ends.size();
    first_ray[s] = total;
    origins[s] = octomap::point3d(rays.origin.x(), rays.origin.y(), rays.origin.z());
    octomap::OcTreeKey origin_key;
    if (!tree.coordToKeyChecked(origins[s], origin_key)) continue;
    if (sets.empty()) min_key = max_key = origin_key;
    sets.push_back({s, 0, rays.ends.size()});
    total += rays.ends.size();
    for (int a = 0; a < 3; ++a) {
      min_key[a] = std::min(min_key[a], origin_key[a]);
      max_key[a] = std::max(max_key[a], origin_key[a]);
    }
  }
  if (sets.empty()) return stats;
  const unsigned parts =
      static_cast<unsigned>(std::clamp<std::size_t>(total / kMinRaysPerThread, 1, threads_));

  // Per ray: its end voxel and the voxel where its free space ends, and the box of both.
  end_keys_.resize(total);
  free_keys_.resize(total);
  end_valid_.assign(total, 0);
  free_valid_.assign(total, 0);
  RunParts(parts, [&](unsigned part) {
    Worker& worker = *workers_[part];
    octomap::OcTreeKey lo = min_key, hi = max_key;
    for (const Span& span : PartOf(sets, first_ray, total, part, parts)) {
      const robotio::DepthRays& rays = *ray_sets[span.set];
      for (std::size_t i = span.begin; i < span.end; ++i) {
        const std::size_t j = first_ray[span.set] + i;
        const Eigen::Vector3f& p = rays.ends[i];
        octomap::OcTreeKey& key = end_keys_[j];
        if (!tree.coordToKeyChecked(octomap::point3d(p.x(), p.y(), p.z()), key)) continue;
        end_valid_[j] = 1;
        for (int a = 0; a < 3; ++a) {
          lo[a] = std::min(lo[a], key[a]);
          hi[a] = std::max(hi[a], key[a]);
        }
        const std::optional<Eigen::Vector3f> free_end = FreeSpaceEnd(rays, i, rules);
        if (!free_end) continue;
        free_keys_[j] = key;
        if (*free_end != p && !tree.coordToKeyChecked(
                                  octomap::point3d(free_end->x(), free_end->y(), free_end->z()),
                                  free_keys_[j])) {
          continue;
        }
        free_valid_[j] = 1;  // Between the origin and the end: inside the box.
      }
    }
    worker.min_key = lo;
    worker.max_key = hi;
  });
  for (unsigned part = 0; part < parts; ++part) {
    for (int a = 0; a < 3; ++a) {
      min_key[a] = std::min(min_key[a], workers_[part]->min_key[a]);
      max_key[a] = std::max(max_key[a], workers_[part]->max_key[a]);
    }
  }

  // Hits and free space, each part in its own blocks: per origin, one trace per distinct
  // free-space end voxel, to its centre (OctoMap's discretise; the free end of a hit with
  // a margin lies between the origin and the hit).
  RunParts(parts, [&](unsigned part) {
    Worker& worker = *workers_[part];
    worker.blocks.Reset(min_key, max_key);
    worker.traced = 0;
    for (const Span& span : PartOf(sets, first_ray, total, part, parts)) {
      const robotio::DepthRays& rays = *ray_sets[span.set];
      worker.unique_ends.clear();
      for (std::size_t i = span.begin; i < span.end; ++i) {
        const std::size_t j = first_ray[span.set] + i;
        if (end_valid_[j] == 0) continue;
        if (rays.hit[i]) SetBit(worker.blocks.BlockFor(end_keys_[j]).hit, end_keys_[j]);
        if (free_valid_[j] == 0) continue;
        if (SetBit(worker.blocks.BlockFor(free_keys_[j]).end, free_keys_[j])) {
          worker.unique_ends.push_back(free_keys_[j]);
        }
      }
      worker.traced += worker.unique_ends.size();
      for (const octomap::OcTreeKey& end_key : worker.unique_ends) {
        ClearBit(worker.blocks.BlockFor(end_key).end, end_key);  // For the next origin.
        if (!tree.computeRayKeys(origins[span.set], tree.keyToCoord(end_key), worker.key_ray)) {
          continue;
        }
        for (const octomap::OcTreeKey& key : worker.key_ray) {
          SetBit(worker.blocks.BlockFor(key).free, key);
        }
      }
    }
  });
  ScanBlocks& blocks = workers_[0]->blocks;
  stats.traced_rays = workers_[0]->traced;
  for (unsigned part = 1; part < parts; ++part) {
    blocks.Merge(workers_[part]->blocks);
    stats.traced_rays += workers_[part]->traced;
  }

  hit_keys_.clear();
  for (const ScanBlock& block : blocks.blocks()) {
    for (std::uint32_t w = 0; w < 8; ++w) {
      for (std::uint64_t bits = block.hit[w]; bits != 0; bits &= bits - 1) {
        const auto bit = static_cast<std::uint32_t>(__builtin_ctzll(bits));
        hit_keys_.push_back(KeyOfBit(block, w * 64 + bit));
      }
    }
  }
  if (rules.surface_band) {
    ClearSurfaceBand(blocks, hit_keys_,
                     rules.floor_plane ? std::optional<octomap::key_type>(FloorLayerKey(tree))
                                       : std::nullopt);
  }
  UpdateTree(tree, blocks.blocks(), rules, order_, &stats);
  return stats;
}

octomap::key_type FloorLayerKey(const DualOcTree& tree) {
  return tree.coordToKey(0.5 * tree.getResolution());
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

}  // namespace dynamap::mapping
