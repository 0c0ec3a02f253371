// Fills narrow unknown gaps inside seen floor. Far from the Kinects, rays meet the floor at
// grazing angles and sample it in stripes sparser than the voxels, so the projected floor
// is speckled with unknown cells; inflated like obstacles they would cut the seen floor
// into islands the planner cannot cross, and every speckle would be a frontier.
#pragma once

#include "dynamap/planning/GridMap.hpp"

namespace dynamap::planning {

// Morphological closing of the navigable cells with a disc of diameter `max_gap_m`: unknown
// cells it covers become navigable. Obstacles and holes are never changed, and the outer
// edge of the seen floor does not grow (closing only fills concavities and gaps narrower
// than the disc). Returns the number of cells filled.
int CloseFloorGaps(GridMap& map, double max_gap_m);

// The same for obstacles: unknown gaps this narrow in a seen wall (cells its oblique scans
// missed) become obstacle, so they are neither passages nor frontiers into the wall.
int CloseWallGaps(GridMap& map, double max_gap_m);

// Marks unknown cells within `radius_m` of (x_m, y_m) navigable where they connect to it
// (4-connected) without crossing an obstacle or a hole: floor the robot stood on or the
// operator put it down on, never the far side of a wall. Returns the cells marked.
int AssumeFloorAround(GridMap& map, double x_m, double y_m, double radius_m);

// Unknown cells within `radius_m` of a hole cell become hole: a stair pit's edge is seen
// only where free space below it was observed, and unknown cells are inflated less than
// the robot's radius, so without this a path may run with the footprint over the unseen
// part of the edge. Returns the cells marked.
int ExtendHolesIntoUnknown(GridMap& map, double radius_m);

}  // namespace dynamap::planning
