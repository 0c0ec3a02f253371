#include "dynamap/planning/MapProjection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynamap::planning {

CellState ProjectColumn(const VoxelMapView& view, double x_m, double y_m,
                        const ProjectionConfig& config) {
  return ProjectColumnDetailed(view, x_m, y_m, config).state;
}

ColumnProjection ProjectColumnDetailed(const VoxelMapView& view, double x_m, double y_m,
                                       const ProjectionConfig& config, bool dynamic_obstacles) {
  const double r = view.Resolution();
  // Voxel centres at (k + 0.5)·r, from the bottom of the hole search to the robot's top.
  const int k_min = static_cast<int>(std::floor(-(config.floor_band_m + config.hole_depth_m) / r));
  const int k_max = static_cast<int>(std::floor(config.robot_height_m / r));
  bool floor_seen = false;
  bool free_below_floor = false;
  bool dynamic_obstacle = false;
  for (int k = k_min; k <= k_max; ++k) {
    const double z = (k + 0.5) * r;
    const Eigen::Vector3f p(static_cast<float>(x_m), static_cast<float>(y_m), static_cast<float>(z));
    if (z > config.step_height_m) {
      // Dynamic obstacles (people) block the planner although they never enter the static map.
      if (view.StaticState(p) == VoxelState::kOccupied) return {CellState::kObstacle, false};
      dynamic_obstacle = dynamic_obstacle || (dynamic_obstacles &&
                                              view.DynamicState(p) == VoxelState::kOccupied);
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
  if (dynamic_obstacle) return {CellState::kObstacle, true};
  if (floor_seen) return {CellState::kNavigable, false};
  if (free_below_floor) return {CellState::kHole, false};
  return {CellState::kUnknown, false};
}

MapProjector::MapProjector(GridMap area, ProjectionConfig config)
    : map_(std::move(area)),
      config_(config),
      dynamic_since_s_(map_.cells.size(), std::numeric_limits<double>::quiet_NaN()) {
  std::fill(map_.cells.begin(), map_.cells.end(), CellState::kUnknown);
}

std::vector<int> MapProjector::ProjectAll(const VoxelMapView& view) {
  std::vector<int> all(map_.cells.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return Reproject(view, all, 0.0);
}

std::vector<int> MapProjector::Update(const VoxelMapView& view,
                                      const std::vector<Eigen::Vector2f>& touched_xy,
                                      double now_s) {
  std::vector<int> cells;
  cells.reserve(touched_xy.size());
  for (const Eigen::Vector2f& p : touched_xy) {
    const GridIndex c = map_.CellAt(p.x(), p.y());
    if (map_.Contains(c)) cells.push_back(map_.Index(c));
  }
  std::sort(cells.begin(), cells.end());
  cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  return Reproject(view, cells, now_s);
}

void MapProjector::Refresh(const std::vector<Eigen::Vector2f>& hit_xy, double now_s) {
  for (const Eigen::Vector2f& p : hit_xy) {
    const GridIndex c = map_.CellAt(p.x(), p.y());
    if (!map_.Contains(c)) continue;
    double& since = dynamic_since_s_[map_.Index(c)];
    if (!std::isnan(since)) since = now_s;
  }
}

std::vector<int> MapProjector::DynamicObstacleCells() const {
  std::vector<int> cells;
  for (const int i : dynamic_cells_) {
    // A released cell shows what lies under the trace, never an obstacle of its own.
    if (map_.cells[i] == CellState::kObstacle) cells.push_back(i);
  }
  return cells;
}

std::vector<int> MapProjector::ExpireDynamicObstacles(const VoxelMapView& view, double now_s) {
  if (config_.dynamic_obstacle_ttl_s <= 0.0) return {};
  std::vector<int> expired;
  for (const int i : dynamic_cells_) {
    // Released cells keep their time (a scan passing over them does not re-stamp them,
    // only one hitting something there: Refresh) and are not re-projected on every call.
    if (now_s - dynamic_since_s_[i] > config_.dynamic_obstacle_ttl_s &&
        map_.cells[i] == CellState::kObstacle) {
      expired.push_back(i);
    }
  }
  return expired.empty() ? expired : Reproject(view, expired, now_s);
}

std::vector<int> MapProjector::Reproject(const VoxelMapView& view, const std::vector<int>& cells,
                                         double now_s) {
  const double ttl = config_.dynamic_obstacle_ttl_s;
  std::vector<int> changed;
  for (const int i : cells) {
    const GridIndex c = map_.Cell(i);
    const double x = map_.CenterX(c.x);
    const double y = map_.CenterY(c.y);
    ColumnProjection p = ProjectColumnDetailed(view, x, y, config_);
    double& since = dynamic_since_s_[i];
    if (!p.dynamic_only) {
      since = std::numeric_limits<double>::quiet_NaN();
    } else if (std::isnan(since)) {
      since = now_s;
      dynamic_cells_.push_back(i);
    } else if (ttl > 0.0 && now_s - since > ttl) {
      p = ProjectColumnDetailed(view, x, y, config_, false);  // What lies under the trace.
    }
    if (p.state != map_.cells[i]) {
      map_.cells[i] = p.state;
      changed.push_back(i);
    }
  }
  // Forget cells no longer blocked by the dynamic map alone.
  dynamic_cells_.erase(std::remove_if(dynamic_cells_.begin(), dynamic_cells_.end(),
                                      [&](int i) { return std::isnan(dynamic_since_s_[i]); }),
                       dynamic_cells_.end());
  return changed;
}

}  // namespace dynamap::planning
