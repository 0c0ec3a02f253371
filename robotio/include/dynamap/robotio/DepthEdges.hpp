// Where a depth pixel's ray passes close by a nearer surface: at a depth edge, the rays
// just beside the foreground's outline run within a few centimetres of it, through the
// voxels that hold its rim. A thin object seen edge-on (an open door leaf, 4 cm thick) is
// all rim: the rays along it cross its voxels before any ray hits it, and a map that
// counts those crossings as free space takes the leaf for something that appeared there.
#pragma once

#include <cstdint>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"

namespace dynamap::robotio {

// Per pixel (row-major, as frame.depth_mm), the smallest depth z in m among the pixels
// whose measurement lies within `lateral_m` of the pixel's ray, itself included: a
// neighbour at pixel offset r (the larger of |du| and |dv|) and depth z is that close when
// r * z / f <= lateral_m (f the smaller focal length). Depths below `min_mm` are no
// measurement; +infinity where no pixel qualifies. Sound, not exact: neighbours are
// searched in square windows of radius 1, 2, 4, 8, ... px (OpenCV erosions), each window's
// minimum counted when it is that close at the window's radius, so a neighbour may be
// missed but none farther away ever counts.
[[nodiscard]] std::vector<float> NearestDepthAlongside(const DepthFrame& frame, double lateral_m,
                                                       std::uint16_t min_mm);

}  // namespace dynamap::robotio
