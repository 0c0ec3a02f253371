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
// With `side_depth_m` > 0 the columns just outside the image's left and right edges count
// as measured at that depth: the camera does not see what lies beside its view, and the
// rays along an edge ran past a wall's end just outside it (a jamb seen from the corridor)
// with nothing beside them. Rays within lateral_m * f / side_depth_m px of those edges then
// stop near that depth; unseen surfaces at least that deep are all allowed for.
[[nodiscard]] std::vector<float> NearestDepthAlongside(const DepthFrame& frame, double lateral_m,
                                                       std::uint16_t min_mm,
                                                       double side_depth_m = 0.0);

// The Kinect returns no depth where it sees a surface at grazing incidence (from about
// 75 deg), so the far part of a wall or door leaf seen along its face is a gap in the image,
// and the rays just beside that part, which run through the air in the voxels holding the
// face, have no nearer measurement beside them. This fills such gaps for
// NearestDepthAlongside: a pixel without depth (0) within `reach_px` (square window) of a
// measured pixel whose |cos| of incidence (`incidence_cos`, row-major as depth_mm) is below
// kGrazingCos takes the smallest such depth. The surface the gap continues lies at least
// that far where it recedes, as a grazing surface does, so the fill is a near bound.
// Pixels with depth are unchanged; reach_px 0 returns the frame as it is.
inline constexpr float kGrazingCos = 0.4f;  // About 66 deg from the normal.
[[nodiscard]] DepthFrame FillGrazingGaps(const DepthFrame& frame,
                                         const std::vector<float>& incidence_cos, int reach_px,
                                         std::uint16_t min_mm);

}  // namespace dynamap::robotio
