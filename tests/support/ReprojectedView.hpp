// New views of a real depth frame for tests: the frame's points seen from a moved camera
// (same intrinsics), nearest surface per pixel. Uncovered pixels stay missing, as
// disocclusions do in a real camera.
#pragma once

#include <Eigen/Geometry>

#include "dynamap/robotio/DepthFrame.hpp"

namespace dynamap::test {

// T_old_new: the new camera's optical frame in the old one's.
[[nodiscard]] robotio::DepthFrame ReprojectedView(const robotio::DepthFrame& frame,
                                                  const Eigen::Isometry3d& T_old_new);

}  // namespace dynamap::test
