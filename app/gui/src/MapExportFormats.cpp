#include "dynamap/app/gui/MapExportFormats.hpp"

#include <cassert>
#include <filesystem>

#include "dynamap/app/runtime/MissionOutputs.hpp"
#include "dynamap/mapping/MapExport.hpp"
#include "dynamap/mapping/MapFiles.hpp"
#include "dynamap/mapping/PointCloudFiles.hpp"
#include "dynamap/planning/DualMapView.hpp"

namespace dynamap::app::gui {

const std::vector<ExportFormat>& ExportFormats() {
  static const std::vector<ExportFormat> kFormats = {
      {ExportKind::kStaticBinaryTree, "Static map as OctoMap (.bt)…", "OctoMap binary (*.bt)",
       "bt"},
      {ExportKind::kDynamicBinaryTree, "Dynamic map as OctoMap (.bt)…",
       "OctoMap binary (*.bt)", "bt"},
      {ExportKind::kStaticPly, "Static voxels as point cloud (.ply)…", "PLY point cloud (*.ply)",
       "ply"},
      {ExportKind::kDynamicPly, "Dynamic voxels as point cloud (.ply)…",
       "PLY point cloud (*.ply)", "ply"},
      {ExportKind::kStaticPcd, "Static voxels as point cloud (.pcd)…", "PCD point cloud (*.pcd)",
       "pcd"},
      {ExportKind::kDynamicPcd, "Dynamic voxels as point cloud (.pcd)…",
       "PCD point cloud (*.pcd)", "pcd"},
      {ExportKind::kTopDownPng, "Top-down image (.png)…", "PNG image (*.png)", "png"},
      {ExportKind::kRosMap, "2D map for ROS map_server (.yaml + .pgm)…",
       "ROS map (*.yaml)", "yaml"},
  };
  return kFormats;
}

const ExportFormat& FormatOf(ExportKind kind) {
  for (const auto& format : ExportFormats()) {
    if (format.kind == kind) return format;
  }
  assert(false && "every ExportKind has a format");
  return ExportFormats().front();
}

robotio::Status ExportMap(const mapping::DualOcTree& tree, ExportKind kind,
                          const std::string& file) {
  using mapping::MapChannel;
  switch (kind) {
    case ExportKind::kStaticBinaryTree:
      return mapping::ExportBinary(tree, MapChannel::kStatic, file);
    case ExportKind::kDynamicBinaryTree:
      return mapping::ExportBinary(tree, MapChannel::kDynamic, file);
    case ExportKind::kStaticPly:
      return mapping::WritePly(mapping::OccupiedVoxelCentres(tree, MapChannel::kStatic), file);
    case ExportKind::kDynamicPly:
      return mapping::WritePly(mapping::OccupiedVoxelCentres(tree, MapChannel::kDynamic), file);
    case ExportKind::kStaticPcd:
      return mapping::WritePcd(mapping::OccupiedVoxelCentres(tree, MapChannel::kStatic), file);
    case ExportKind::kDynamicPcd:
      return mapping::WritePcd(mapping::OccupiedVoxelCentres(tree, MapChannel::kDynamic), file);
    case ExportKind::kTopDownPng:
      return mapping::WriteTopDownPng(tree, file);
    case ExportKind::kRosMap: {
      const planning::GridMap grid = planning::ProjectSavedMap(tree, planning::ProjectionConfig{});
      if (grid.cells.empty()) return robotio::Error{file + ": the map is empty, no 2D map to write"};
      std::filesystem::path pgm(file);
      pgm.replace_extension(".pgm");
      return runtime::WriteRosMap(grid, pgm.string(), file);
    }
  }
  return robotio::Error{"unknown export kind for " + file};
}

}  // namespace dynamap::app::gui
