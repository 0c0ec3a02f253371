#include "dynamap/robotio/DepthEdges.hpp"

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <limits>

namespace dynamap::robotio {

std::vector<float> NearestDepthAlongside(const DepthFrame& frame, double lateral_m,
                                         std::uint16_t min_mm) {
  constexpr std::uint16_t kNone = std::numeric_limits<std::uint16_t>::max();
  std::vector<float> nearest(frame.depth_mm.size(), std::numeric_limits<float>::infinity());
  if (!frame.Valid()) return nearest;
  cv::Mat window(frame.height, frame.width, CV_16UC1);  // Minimum within radius `radius`.
  std::uint16_t closest = kNone;
  for (int v = 0; v < frame.height; ++v) {
    auto* row = window.ptr<std::uint16_t>(v);
    for (int u = 0; u < frame.width; ++u) {
      const std::uint16_t d = frame.At(u, v);
      row[u] = d < min_mm ? kNone : d;
      closest = std::min(closest, row[u]);
    }
  }
  if (closest == kNone) return nearest;
  const double f = std::min(frame.intrinsics.fx, frame.intrinsics.fy);
  // Square windows of radius 0, 1, 2, 4, 8, ... px: a window's minimum counts when it is
  // near enough at its own offset bound, so no pixel farther than lateral_m ever counts.
  for (int radius = 0, previous = 0;; previous = radius, radius = std::max(1, 2 * radius)) {
    if (radius * (closest * 0.001) / f > lateral_m) break;  // Not even the closest is.
    if (radius > previous) {
      const int grow = radius - previous;
      cv::erode(window, window,
                cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * grow + 1, 2 * grow + 1)));
    }
    for (int v = 0; v < frame.height; ++v) {
      const auto* row = window.ptr<std::uint16_t>(v);
      for (int u = 0; u < frame.width; ++u) {
        const std::uint16_t m = row[u];
        if (m == kNone || radius * (m * 0.001) / f > lateral_m) continue;
        float& n = nearest[v * frame.width + u];
        n = std::min(n, static_cast<float>(m) * 0.001f);
      }
    }
    if (radius >= std::max(frame.width, frame.height)) break;
  }
  return nearest;
}

}  // namespace dynamap::robotio
