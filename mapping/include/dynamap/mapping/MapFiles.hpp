// Map files of the dual map (thesis 4.3): the custom .ot with both channels, standard
// OctoMap .bt exports of each channel (octovis opens them), and import of plain .bt/.ot.
#pragma once

#include <octomap/OcTree.h>

#include <memory>
#include <string>

#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::mapping {

enum class MapChannel { kStatic, kDynamic };

// Writes the dual tree as an OctoMap .ot (type DualOcTree::kTreeType), atomically.
[[nodiscard]] robotio::Status SaveDualMap(const DualOcTree& tree, const std::string& file);

// Opens a map: a dual .ot exactly as saved, or a plain OctoMap .bt / OcTree .ot as a
// static map (dynamic channel free). A file that is not an OctoMap file, holds another tree
// type, or is truncated is an Error naming the file.
[[nodiscard]] robotio::Expected<std::unique_ptr<DualOcTree>> LoadMap(const std::string& file);

// One channel as a standard octomap::OcTree with the same structure and that channel's
// log-odds in every node.
[[nodiscard]] std::unique_ptr<octomap::OcTree> ChannelAsOcTree(const DualOcTree& tree,
                                                                MapChannel channel);

// One channel as an OctoMap binary tree (.bt), atomically. The tree is written as it is
// (no pruning), so a .bt imported with LoadMap re-exports byte-identical.
[[nodiscard]] robotio::Status ExportBinary(const DualOcTree& tree, MapChannel channel,
                                           const std::string& file);

}  // namespace dynamap::mapping
