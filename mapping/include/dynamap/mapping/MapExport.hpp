// Views of the dual map for inspection (DESIGN.md, mapping and app export): occupied voxel
// centres per channel and a top-down image with static (grey) and dynamic (red) voxels.
#pragma once

#include <string>

#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/mapping/MapFiles.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::mapping {

// Centres of the occupied leaf-size voxels of one channel (map frame); a pruned node
// contributes every leaf voxel it stands for, so the density is uniform.
[[nodiscard]] robotio::PointList OccupiedVoxelCentres(const DualOcTree& tree,
                                                      MapChannel channel);

// Top-down PNG, one square per leaf column (maps under 300 voxels across are drawn at 2–8
// pixels per voxel), x to the right and y up: red where any voxel of the column is
// dynamic-occupied, grey (darker = taller) where it is static-occupied, white where only
// free space was seen, light blue-grey where nothing was observed.
[[nodiscard]] robotio::Status WriteTopDownPng(const DualOcTree& tree, const std::string& file);

}  // namespace dynamap::mapping
