#include "dynamap/robotio/DepthEdges.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <limits>

namespace dynamap::robotio {

std::vector<float> NearestDepthAlongside(const DepthFrame& frame, double lateral_m,
                                         std::uint16_t min_mm) {
  constexpr std::uint16_t kNone = std::numeric_limits<std::uint16_t>::max();
  const float inf = std::numeric_limits<float>::infinity();
  if (!frame.Valid()) return std::vector<float>(frame.depth_mm.size(), inf);
  // Depth in mm, kNone where there is no measurement.
  cv::Mat window(frame.height, frame.width, CV_16UC1);
  for (int v = 0; v < frame.height; ++v) {
    auto* row = window.ptr<std::uint16_t>(v);
    for (int u = 0; u < frame.width; ++u) {
      const std::uint16_t d = frame.At(u, v);
      row[u] = d < min_mm ? kNone : d;
    }
  }
  double closest = 0.0;
  cv::minMaxLoc(window, &closest);
  cv::Mat nearest = window.clone();  // Radius 0: each pixel's own measurement.
  const double f = std::min(frame.intrinsics.fx, frame.intrinsics.fy);
  // Square windows of radius 1, 2, 4, 8, ... px: a window's minimum m counts when it is
  // near enough at the window's radius r (r * m / f <= lateral_m), so no pixel farther
  // than lateral_m ever counts.
  cv::Mat near_enough;
  for (int radius = 1, previous = 0; radius <= std::max(frame.width, frame.height);
       previous = radius, radius *= 2) {
    const double limit_mm = lateral_m * f / radius * 1000.0;
    if (closest > limit_mm) break;  // Not even the closest measurement is near enough.
    const int grow = radius - previous;
    cv::erode(window, window,
              cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * grow + 1, 2 * grow + 1)),
              cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(kNone));
    window.copyTo(near_enough);
    near_enough.setTo(kNone, window > limit_mm);
    cv::min(nearest, near_enough, nearest);
  }
  std::vector<float> out(frame.depth_mm.size(), inf);
  for (int v = 0; v < frame.height; ++v) {
    const auto* row = nearest.ptr<std::uint16_t>(v);
    for (int u = 0; u < frame.width; ++u) {
      if (row[u] != kNone) out[v * frame.width + u] = static_cast<float>(row[u]) * 0.001f;
    }
  }
  return out;
}

}  // namespace dynamap::robotio
