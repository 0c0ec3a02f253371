// The collision guard's complement for what the Kinects cannot see: nothing nearer than
// their 0.5 m minimum range, nothing beside or behind the base. Door posts and desk corners
// pass out of view before the base reaches them, so while driving the known obstacles of
// the projected map are checked around where the footprint will be shortly. Holes (a stair
// pit) count as obstacles: the Kinects see no floor within robotio::FloorBlindRadius (1.25 m
// for the shipped rig), so a pit's edge is never in the collision guard's view when the
// base reaches it.
#pragma once

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"

namespace dynamap::planning {

// Distance from (x_m, y_m) (map frame) to the nearest obstacle or hole cell's centre within
// `search_m`, or `search_m` when there is none that near.
[[nodiscard]] double DistanceToKnownObstacle(const GridMap& map, double x_m, double y_m,
                                             double search_m);

// True when driving `command` for `horizon_s` from `pose` would bring the footprint
// (radius `footprint_m`) into a known obstacle, heading into it (the distance shrinks by
// more than 30 % of the distance travelled: passing a door post abeam is allowed); turning
// in place is never refused.
[[nodiscard]] bool DrivesIntoKnownObstacle(const GridMap& map, const robotio::Pose2D& pose,
                                           const robotio::VelocityCommand& command,
                                           double footprint_m, double horizon_s);

}  // namespace dynamap::planning
