#include "ReprojectedView.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::test {

robotio::DepthFrame ReprojectedView(const robotio::DepthFrame& frame,
                                    const Eigen::Isometry3d& T_old_new) {
  robotio::DepthFrame view = frame;
  std::fill(view.depth_mm.begin(), view.depth_mm.end(), std::uint16_t{0});
  const Eigen::Isometry3f T_new_old = T_old_new.inverse().cast<float>();
  const auto& k = frame.intrinsics;
  for (const Eigen::Vector3f& p_old : robotio::DepthToOrganizedPoints(frame)) {
    if (!p_old.allFinite()) continue;
    const Eigen::Vector3f p = T_new_old * p_old;
    if (p.z() <= 0.0f) continue;
    const long u = std::lround(k.fx * p.x() / p.z() + k.cx);
    const long v = std::lround(k.fy * p.y() / p.z() + k.cy);
    if (u < 0 || v < 0 || u >= view.width || v >= view.height) continue;
    const double mm = std::round(p.z() * 1000.0);
    if (mm <= 0.0 || mm > std::numeric_limits<std::uint16_t>::max()) continue;
    std::uint16_t& out = view.depth_mm[static_cast<std::size_t>(v * view.width + u)];
    if (out == 0 || mm < out) out = static_cast<std::uint16_t>(mm);
  }
  return view;
}

}  // namespace dynamap::test
