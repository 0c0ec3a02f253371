#include "dynamap/planning/MapProjection.hpp"

#include <algorithm>
#include <cmath>

namespace dynamap::planning {

CellState ProjectColumn(const VoxelMapView& view, double x_m, double y_m,
                        const ProjectionConfig& config) {
  const double r = view.Resolution();
  // Voxel centres at (k + 0.5)·r, from the bottom of the hole search to the robot's top.
  const int k_min = static_cast<int>(std::floor(-(config.floor_band_m + config.hole_depth_m) / r));
  const int k_max = static_cast<int>(std::floor(config.robot_height_m / r));
  bool floor_seen = false;
  bool free_below_floor = false;
  for (int k = k_min; k <= k_max; ++k) {
    const double z = (k + 0.5) * r;
    const Eigen::Vector3f p(static_cast<float>(x_m), static_cast<float>(y_m), static_cast<float>(z));
    if (z > config.step_height_m) {
      // Dynamic obstacles (people) block the planner although they never enter the static map.
      if (view.StaticState(p) == VoxelState::kOccupied ||
          view.DynamicState(p) == VoxelState::kOccupied) {
        return CellState::kObstacle;
      }
      continue;
    }
    const VoxelState s = view.StaticState(p);
    if (std::abs(z) <= config.floor_band_m) {
      // Floor that went to the dynamic channel (grazing rays cleared it first) is still
      // something the wheels can stand on.
      if (s == VoxelState::kOccupied || view.DynamicState(p) == VoxelState::kOccupied) {
        floor_seen = true;
      }
      // Free floor-band voxels are no hole evidence: rays traced to the centres of floor
      // voxels graze through the band just before real floor (both layers around z = 0).
    } else if (z < -config.floor_band_m) {
      if (s == VoxelState::kFree) free_below_floor = true;
      // Floor slightly below the band (a ramp) still counts as floor when it is occupied.
    } else if (s == VoxelState::kOccupied) {
      floor_seen = true;  // Clutter below step height: drivable like floor.
    }
  }
  if (floor_seen) return CellState::kNavigable;
  if (free_below_floor) return CellState::kHole;
  return CellState::kUnknown;
}

MapProjector::MapProjector(GridMap area, ProjectionConfig config)
    : map_(std::move(area)), config_(config) {
  std::fill(map_.cells.begin(), map_.cells.end(), CellState::kUnknown);
}

std::vector<int> MapProjector::ProjectAll(const VoxelMapView& view) {
  std::vector<int> all(map_.cells.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return Reproject(view, all);
}

std::vector<int> MapProjector::Update(const VoxelMapView& view,
                                      const std::vector<Eigen::Vector2f>& touched_xy) {
  std::vector<int> cells;
  cells.reserve(touched_xy.size());
  for (const Eigen::Vector2f& p : touched_xy) {
    const GridIndex c = map_.CellAt(p.x(), p.y());
    if (map_.Contains(c)) cells.push_back(map_.Index(c));
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return Reproject(view, cells);
}

std::vector<int> MapProjector::Reproject(const VoxelMapView& view, const std::vector<int>& cells) {
  std::vector<int> changed;
  for (const int i : cells) {
    const GridIndex c = map_.Cell(i);
    const CellState s = ProjectColumn(view, map_.CenterX(c.x), map_.CenterY(c.y), config_);
    if (s != map_.cells[i]) {
      map_.cells[i] = s;
      changed.push_back(i);
    }
  }
  return changed;
}

}  // namespace dynamap::planning
