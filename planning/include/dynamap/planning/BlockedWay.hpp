// When no path leads to the goal: is it people that block the way (obstacles of the dynamic
// map alone)? Then the robot waits for them for a while, looking the way it wants to go so
// that the Kinects see it clear, instead of giving the target up. A person walking to and
// fro between the robot and a room's only door would otherwise get every target beyond
// the door blacklisted, one after the other.
#pragma once

#include <optional>
#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TraversalGrid.hpp"

namespace dynamap::planning {

// `grid` with the cells that only the dynamic map blocks (given as indices) drivable.
[[nodiscard]] GridMap WithoutDynamicObstacles(const GridMap& grid,
                                              const std::vector<int>& dynamic_obstacles);

struct BlockedWayConfig {
  double wait_s = 10.0;       // s the robot waits before the target counts as unreachable.
  double look_ahead_m = 1.0;  // m along the way round the people: where to look meanwhile.
};

struct BlockedWayVerdict {
  bool wait = false;       // Wait; otherwise the goal is unreachable.
  GridIndex look_at;       // Cell to face while waiting.
  double blocked_for_s = 0.0;
};

class BlockedWay {
 public:
  explicit BlockedWay(BlockedWayConfig config = {}) : config_(config) {}

  // No path leads from `robot` to `goal` on the grid with every obstacle. `passable` is the
  // same grid without the dynamic map's obstacles (null when there are none). Waiting
  // time counts from the first of an unbroken series of blocked plans, whatever their goal.
  [[nodiscard]] BlockedWayVerdict Judge(const TraversalGrid* passable, GridIndex robot,
                                        GridIndex goal, double resolution_m, double now_s);
  // A path was found: the next blockage starts a new wait.
  void Clear() { since_s_.reset(); }

 private:
  BlockedWayConfig config_;
  std::optional<double> since_s_;
};

}  // namespace dynamap::planning
