// A deliberately plain implementation of the dual-map scan rules (hash sets of keys, one
// root-to-leaf walk per voxel, a full bottom-up aggregation and pruning pass at the end),
// which the batched ScanIntegrator must reproduce exactly.
#pragma once

#include <vector>

#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/mapping/UpdateRules.hpp"
#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::mapping::testing {

// One scan from one or several origins: every voxel updated once, a hit from any set wins.
void ReferenceInsert(DualOcTree& tree, const std::vector<robotio::DepthRays>& ray_sets,
                     const UpdateRules& rules);

}  // namespace dynamap::mapping::testing
