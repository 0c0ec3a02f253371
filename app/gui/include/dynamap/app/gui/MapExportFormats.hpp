// The exports the Maps workspace offers, each a call into the core libraries' file code:
// one channel as an OctoMap .bt or as voxel centres in .ply/.pcd, the top-down PNG, and
// the projected 2D map for ROS map_server (.yaml beside a .pgm).
#pragma once

#include <string>
#include <vector>

#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::app::gui {

enum class ExportKind {
  kStaticBinaryTree,
  kDynamicBinaryTree,
  kStaticPly,
  kDynamicPly,
  kStaticPcd,
  kDynamicPcd,
  kTopDownPng,
  kRosMap,
};

struct ExportFormat {
  ExportKind kind;
  const char* label;   // menu text, e.g. "Static map as OctoMap (.bt)…".
  const char* filter;  // file dialog filter, e.g. "OctoMap binary (*.bt)".
  const char* suffix;  // appended when the chosen name has none, e.g. "bt".
};

// Every export in menu order.
[[nodiscard]] const std::vector<ExportFormat>& ExportFormats();
[[nodiscard]] const ExportFormat& FormatOf(ExportKind kind);

// Writes `tree` as `kind` to `file`; errors name the file and the cause.
[[nodiscard]] robotio::Status ExportMap(const mapping::DualOcTree& tree, ExportKind kind,
                                        const std::string& file);

}  // namespace dynamap::app::gui
