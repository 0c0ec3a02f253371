// How close to the base the Kinects of a rig can see the floor. Mounted at 0.5-0.6 m and
// pitched only a little down, they cannot see the floor nearer than about a metre, so the
// ring around where the robot stands stays unknown in the map unless something says what
// is there.
#pragma once

#include "dynamap/robotio/Rig.hpp"

namespace dynamap::robotio {

// For each Kinect, the floor (z = 0 in base) seen along the image edge nearest the robot:
// the largest horizontal distance from the base origin of those floor points (within the
// Kinect's depth range). The rig's value is the largest over its Kinects: beyond it, every
// direction a Kinect looks in sees the floor. 0 when no Kinect sees the floor at all.
[[nodiscard]] double FloorBlindRadius(const Rig& rig);

}  // namespace dynamap::robotio
