#include "dynamap/planning/CostField.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <opencv2/imgproc.hpp>

namespace dynamap::planning {

namespace {

// Distance (cells) from every cell to the nearest cell `is_source` accepts; sources get 0.
cv::Mat DistanceTo(const GridMap& map, const std::function<bool(CellState)>& is_source) {
  // distanceTransform measures the distance to the nearest zero pixel: zero = source.
  cv::Mat mask(map.height, map.width, CV_8UC1);
  for (int y = 0; y < map.height; ++y) {
    auto* row = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < map.width; ++x) {
      row[x] = is_source(map.cells[static_cast<std::size_t>(y) * map.width + x]) ? 0 : 255;
    }
  }
  cv::Mat distance;
  cv::distanceTransform(mask, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  return distance;
}

}  // namespace

TraversalGrid BuildTraversalGrid(const GridMap& map, const CostFieldConfig& config) {
  TraversalGrid grid(map.width, map.height, 0.0);
  if (map.width == 0 || map.height == 0) return grid;
  const cv::Mat to_obstacle = DistanceTo(
      map, [](CellState s) { return s == CellState::kObstacle || s == CellState::kHole; });
  cv::Mat to_hole;
  if (config.hole_margin_m > 0.0 &&
      std::find(map.cells.begin(), map.cells.end(), CellState::kHole) != map.cells.end()) {
    to_hole = DistanceTo(map, [](CellState s) { return s == CellState::kHole; });
  }
  cv::Mat to_unknown;
  if (config.unknown_is_obstacle) {
    to_unknown = DistanceTo(map, [](CellState s) { return s == CellState::kUnknown; });
  }
  const double radius_cells = config.robot_radius_m / map.resolution_m;
  const double unknown_cells = config.unknown_radius_m / map.resolution_m;
  const double hole_cells = (config.robot_radius_m + config.hole_margin_m) / map.resolution_m;
  const double range_cells = config.proximity_range_m / map.resolution_m;
  for (int y = 0; y < map.height; ++y) {
    const auto* row = to_obstacle.ptr<float>(y);
    const float* unknown_row = to_unknown.empty() ? nullptr : to_unknown.ptr<float>(y);
    const float* hole_row = to_hole.empty() ? nullptr : to_hole.ptr<float>(y);
    for (int x = 0; x < map.width; ++x) {
      const double d = row[x];
      double& p = grid.penalty[static_cast<std::size_t>(y) * map.width + x];
      const bool near_unknown =
          unknown_row != nullptr && (unknown_row[x] == 0.0f || unknown_row[x] < unknown_cells);
      const bool near_hole = hole_row != nullptr && hole_row[x] < hole_cells;
      if (d == 0.0 || d < radius_cells || near_unknown || near_hole) {
        p = kInfinity;
      } else if (range_cells > 0.0 && d < radius_cells + range_cells) {
        p = config.proximity_weight * (1.0 - (d - radius_cells) / range_cells);
      }
    }
  }
  return grid;
}

void FreeWayOut(TraversalGrid& grid, const GridMap& map, GridIndex robot,
                const CostFieldConfig& config) {
  if (!grid.Contains(robot) || !grid.Blocked(robot) || grid.width != map.width ||
      grid.height != map.height) {
    return;
  }
  const cv::Mat to_obstacle = DistanceTo(
      map, [](CellState s) { return s == CellState::kObstacle || s == CellState::kHole; });
  const cv::Mat to_hole = DistanceTo(map, [](CellState s) { return s == CellState::kHole; });
  const auto distance = [](const cv::Mat& d, GridIndex c) { return d.at<float>(c.y, c.x); };
  const float robot_to_obstacle = distance(to_obstacle, robot);
  const float robot_to_hole = distance(to_hole, robot);
  const double reach_cells = (config.robot_radius_m + config.hole_margin_m) / map.resolution_m;
  std::vector<bool> visited(grid.penalty.size(), false);
  std::vector<GridIndex> open = {robot};
  visited[static_cast<std::size_t>(grid.Index(robot))] = true;
  while (!open.empty()) {
    const GridIndex c = open.back();
    open.pop_back();
    grid.penalty[grid.Index(c)] = kStandingCellPenalty;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const GridIndex n{c.x + dx, c.y + dy};
        if (!grid.Contains(n) || !grid.Blocked(n)) continue;
        const auto index = static_cast<std::size_t>(grid.Index(n));
        if (visited[index] || map.At(n) != CellState::kNavigable ||
            std::hypot(n.x - robot.x, n.y - robot.y) > reach_cells ||
            distance(to_obstacle, n) < robot_to_obstacle || distance(to_hole, n) < robot_to_hole) {
          continue;
        }
        visited[index] = true;
        open.push_back(n);
      }
    }
  }
}

double Clearance(const TraversalGrid& grid, GridIndex cell, const CostFieldConfig& config) {
  if (grid.Blocked(cell)) return 0.0;
  const double p = grid.penalty[grid.Index(cell)];
  if (p <= 0.0 || config.proximity_weight <= 0.0) return config.proximity_range_m;
  return config.proximity_range_m * (1.0 - p / config.proximity_weight);
}

TraversalGrid TraversalFromPassable(int width, int height, const std::vector<bool>& passable) {
  assert(passable.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  TraversalGrid grid(width, height, 0.0);
  for (std::size_t i = 0; i < passable.size(); ++i) {
    if (!passable[i]) grid.penalty[i] = kInfinity;
  }
  return grid;
}

std::vector<CellChange> DiffGrids(const TraversalGrid& before, const TraversalGrid& after) {
  assert(before.width == after.width && before.height == after.height);
  std::vector<CellChange> changes;
  for (std::size_t i = 0; i < after.penalty.size(); ++i) {
    if (before.penalty[i] != after.penalty[i]) {
      changes.push_back({static_cast<int>(i), after.penalty[i]});
    }
  }
  return changes;
}

}  // namespace dynamap::planning
