// The dual static/dynamic OctoMap (mapping::DualMap, thesis 4.2) seen through the two
// queries the map projection needs (thesis 6.1), plus the columns a scan touched.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/planning/MapProjection.hpp"
#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::planning {

class DualMapView : public VoxelMapView {
 public:
  explicit DualMapView(const mapping::DualMap& map) : map_(map) {}

  [[nodiscard]] double Resolution() const override { return map_.tree().getResolution(); }
  [[nodiscard]] VoxelState StaticState(const Eigen::Vector3f& p_map) const override {
    return Convert(map_.StaticState(p_map));
  }
  [[nodiscard]] VoxelState DynamicState(const Eigen::Vector3f& p_map) const override {
    return Convert(map_.DynamicState(p_map));
  }

 private:
  [[nodiscard]] static VoxelState Convert(mapping::VoxelState s) {
    switch (s) {
      case mapping::VoxelState::kFree:
        return VoxelState::kFree;
      case mapping::VoxelState::kOccupied:
        return VoxelState::kOccupied;
      case mapping::VoxelState::kUnknown:
        break;
    }
    return VoxelState::kUnknown;
  }

  const mapping::DualMap& map_;
};

// A whole saved dual map (a loaded .ot, or a plain .bt as its static channel) projected
// over the x/y extent of its known voxels at its own resolution, the floor at map z = 0
// as in every dynamap map: what it looks like to the planner, e.g. for a ROS map_server
// export. An empty tree gives an empty grid.
[[nodiscard]] GridMap ProjectSavedMap(const mapping::DualOcTree& tree,
                                      const ProjectionConfig& config);

// Centres (map frame x, y) of the grid columns the rays of one scan pass through, each
// once: what MapProjector::Update needs after DualMap::InsertRays with the same rays.
[[nodiscard]] std::vector<Eigen::Vector2f> TouchedColumns(const robotio::DepthRays& rays,
                                                          const GridMap& area);

// Centres of the grid columns where rays of one scan ended on something between `min_z_m`
// and `max_z_m` (map frame), each once: what MapProjector::Refresh needs.
[[nodiscard]] std::vector<Eigen::Vector2f> HitColumns(const robotio::DepthRays& rays,
                                                      const GridMap& area, double min_z_m,
                                                      double max_z_m);

}  // namespace dynamap::planning
