// Dual 3D map → projected 2D grid (thesis 6.1): per map column, obstacles in the robot's
// height band (static or dynamic), holes where the floor is missing or free space shows
// below it, navigable where floor was seen; re-projected only where a map update touched.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "dynamap/planning/GridMap.hpp"

namespace dynamap::planning {

enum class VoxelState { kUnknown, kFree, kOccupied };

// What the projection reads from the dual static/dynamic map (mapping::DualMap offers the
// same two queries; an adapter forwards them), so planning tests run on synthetic maps.
class VoxelMapView {
 public:
  virtual ~VoxelMapView() = default;
  [[nodiscard]] virtual double Resolution() const = 0;  // m, voxel edge.
  [[nodiscard]] virtual VoxelState StaticState(const Eigen::Vector3f& p_map) const = 0;
  [[nodiscard]] virtual VoxelState DynamicState(const Eigen::Vector3f& p_map) const = 0;
};

struct ProjectionConfig {
  double robot_height_m = 0.9;   // m above the floor (map z = 0): top of robot and mounts.
  double step_height_m = 0.08;   // m, tallest edge the base drives over; higher is obstacle.
  double floor_band_m = 0.06;    // m, |z| within which an occupied voxel is floor evidence.
  double hole_depth_m = 0.3;     // m below the floor band searched for free space (holes).
  double max_floor_gap_m = 0.15; // m, unknown gaps this narrow inside seen floor are floor
                                 // for the planner (CloseFloorGaps); 0 keeps them unknown.
  double dynamic_obstacle_ttl_s = 3.0;  // s a column blocked only by the dynamic map stays
                                 // an obstacle after a scan last hit something in it: a
                                 // person's trace stays in the dynamic map until seen free,
                                 // and one walking to and fro would wall off a room for
                                 // good, while a door closed in front of the robot (dynamic
                                 // by Table 4.1) is hit by every scan that sees it and stays.
                                 // With 10 s, a person pacing past a room's door every 9 s
                                 // kept it shut for the planner; the trace near the robot
                                 // lies in the Kinects' blind zone and is never seen free.
                                 // 0 = dynamic obstacles never expire.
};

struct ColumnProjection {
  CellState state = CellState::kUnknown;
  bool dynamic_only = false;  // An obstacle only because of the dynamic map.
};

// State of the column whose centre is (x_m, y_m) in the map frame. Voxels are sampled at
// the view's resolution: occupied above step height and up to the robot's height (static
// or dynamic) → obstacle; else no floor and free space seen below the floor band →
// hole; else floor seen → navigable; else unknown.
[[nodiscard]] CellState ProjectColumn(const VoxelMapView& view, double x_m, double y_m,
                                      const ProjectionConfig& config);
// The same, saying whether only the dynamic map made it an obstacle; with
// `dynamic_obstacles` false the dynamic map blocks nothing.
[[nodiscard]] ColumnProjection ProjectColumnDetailed(const VoxelMapView& view, double x_m,
                                                     double y_m, const ProjectionConfig& config,
                                                     bool dynamic_obstacles = true);

// Holds the projected grid over a fixed area and keeps it up to date.
class MapProjector {
 public:
  // `area` is the projected grid's geometry; its cells start unknown.
  MapProjector(GridMap area, ProjectionConfig config);

  // Re-projects every column (a loaded map).
  std::vector<int> ProjectAll(const VoxelMapView& view);
  // Re-projects only the columns containing the given map-frame points (those a map update
  // touched) at time `now_s`; returns the indices of cells whose state changed.
  std::vector<int> Update(const VoxelMapView& view, const std::vector<Eigen::Vector2f>& touched_xy,
                          double now_s = 0.0);
  // A scan hit something between step and robot height in these columns at `now_s`: those
  // blocked by the dynamic map alone are still there (their time starts again).
  void Refresh(const std::vector<Eigen::Vector2f>& hit_xy, double now_s);
  // Releases columns blocked only by the dynamic map for longer than the configured time
  // (to what lies under them); returns the indices of cells whose state changed.
  std::vector<int> ExpireDynamicObstacles(const VoxelMapView& view, double now_s);

  [[nodiscard]] const GridMap& map() const { return map_; }
  // Indices of the cells that are obstacles only because of the dynamic map now: people,
  // or a door that has just closed (until it turns static).
  [[nodiscard]] std::vector<int> DynamicObstacleCells() const;

 private:
  std::vector<int> Reproject(const VoxelMapView& view, const std::vector<int>& cells,
                             double now_s);

  GridMap map_;
  ProjectionConfig config_;
  // Per cell: when a scan last saw it blocked by the dynamic map alone (NaN when it is not).
  std::vector<double> dynamic_since_s_;
  std::vector<int> dynamic_cells_;  // Cells with a time in dynamic_since_s_.
};

}  // namespace dynamap::planning
