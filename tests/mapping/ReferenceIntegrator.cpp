#include "ReferenceIntegrator.hpp"

#include <octomap/OcTreeKey.h>

#include <optional>

#include "dynamap/mapping/ScanIntegrator.hpp"

namespace dynamap::mapping::testing {
namespace {

void FinishRecurs(DualOcTree& tree, DualOcTreeNode* node, unsigned depth) {
  if (!tree.nodeHasChildren(node)) return;
  for (unsigned i = 0; i < 8; ++i) {
    if (tree.nodeChildExists(node, i)) FinishRecurs(tree, tree.getNodeChild(node, i), depth + 1);
  }
  if (depth > 0 && tree.pruneNode(node)) return;
  node->updateOccupancyChildren();
}

}  // namespace

void ReferenceInsert(DualOcTree& tree, const std::vector<robotio::DepthRays>& ray_sets,
                     const UpdateRules& rules) {
  octomap::KeySet free_keys, hit_keys;
  octomap::KeyRay ray;
  for (const robotio::DepthRays& rays : ray_sets) {
    const octomap::point3d origin(rays.origin.x(), rays.origin.y(), rays.origin.z());
    octomap::OcTreeKey origin_key;
    if (!tree.coordToKeyChecked(origin, origin_key)) continue;
    for (std::size_t i = 0; i < rays.ends.size(); ++i) {
      octomap::OcTreeKey end;
      const Eigen::Vector3f& p = rays.ends[i];
      if (!tree.coordToKeyChecked(octomap::point3d(p.x(), p.y(), p.z()), end)) continue;
      if (rays.hit[i]) hit_keys.insert(end);
      const std::optional<Eigen::Vector3f> free_end = FreeSpaceEnd(rays, i, rules);
      octomap::OcTreeKey free_key;
      if (!free_end ||
          !tree.coordToKeyChecked(octomap::point3d(free_end->x(), free_end->y(), free_end->z()),
                                  free_key)) {
        continue;
      }
      if (tree.computeRayKeys(origin, tree.keyToCoord(free_key), ray)) {
        free_keys.insert(ray.begin(), ray.end());
      }
    }
  }
  if (rules.surface_band) {
    const octomap::key_type floor_layer = FloorLayerKey(tree);
    for (const octomap::OcTreeKey& key : hit_keys) {
      const int top = rules.floor_plane && key[2] == floor_layer ? 0 : 1;
      for (int dx = -1; dx <= 1; ++dx) {
        for (int dy = -1; dy <= 1; ++dy) {
          for (int dz = -1; dz <= top; ++dz) {
            free_keys.erase(octomap::OcTreeKey(static_cast<octomap::key_type>(key[0] + dx),
                                               static_cast<octomap::key_type>(key[1] + dy),
                                               static_cast<octomap::key_type>(key[2] + dz)));
          }
        }
      }
    }
  }
  octomap::KeySet all = free_keys;
  all.insert(hit_keys.begin(), hit_keys.end());
  if (all.empty()) return;
  const bool root_new = tree.getRoot() == nullptr;
  DualOcTreeNode* root = tree.CreateRoot();
  for (const octomap::OcTreeKey& key : all) {
    DualOcTreeNode* node = root;
    bool is_new = root_new;
    for (unsigned depth = 0; depth < tree.getTreeDepth(); ++depth) {
      const unsigned index =
          octomap::computeChildIdx(key, static_cast<int>(tree.getTreeDepth() - 1 - depth));
      if (tree.nodeChildExists(node, index)) {
        node = tree.getNodeChild(node, index);
        is_new = false;
      } else if (!is_new && !tree.nodeHasChildren(node)) {
        tree.expandNode(node);  // A pruned node: its eight children were observed.
        node = tree.getNodeChild(node, index);
      } else {
        node = tree.createNodeChild(node, index);
        is_new = true;
      }
    }
    const Observation z = hit_keys.count(key) > 0 ? Observation::kOccupied : Observation::kFree;
    const DualLogOdds next =
        ApplyObservation({node->StaticLogOdds(), node->DynamicLogOdds()}, !is_new, z, rules);
    node->SetStaticLogOdds(next.static_log_odds);
    node->SetDynamicLogOdds(next.dynamic_log_odds);
  }
  FinishRecurs(tree, root, 0);
}

}  // namespace dynamap::mapping::testing
