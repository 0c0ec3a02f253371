#include "dynamap/robotio/DepthEdges.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <limits>

namespace dynamap::robotio {

std::vector<float> NearestDepthAlongside(const DepthFrame& frame, double lateral_m,
                                         std::uint16_t min_mm, double side_depth_m) {
  constexpr std::uint16_t kNone = std::numeric_limits<std::uint16_t>::max();
  const float inf = std::numeric_limits<float>::infinity();
  if (!frame.Valid()) return std::vector<float>(frame.depth_mm.size(), inf);
  // Depth in mm, kNone where there is no measurement; one column beside each side edge,
  // the assumed unseen surface there (or nothing).
  const auto side_mm = side_depth_m > 0.0
                           ? static_cast<std::uint16_t>(std::clamp(side_depth_m * 1000.0, 1.0, 65534.0))
                           : kNone;
  cv::Mat window(frame.height, frame.width + 2, CV_16UC1);
  for (int v = 0; v < frame.height; ++v) {
    auto* row = window.ptr<std::uint16_t>(v);
    row[0] = row[frame.width + 1] = side_mm;
    for (int u = 0; u < frame.width; ++u) {
      const std::uint16_t d = frame.At(u, v);
      row[u + 1] = d < min_mm ? kNone : d;
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
    const auto* row = nearest.ptr<std::uint16_t>(v) + 1;
    for (int u = 0; u < frame.width; ++u) {
      if (row[u] != kNone) out[v * frame.width + u] = static_cast<float>(row[u]) * 0.001f;
    }
  }
  return out;
}

DepthFrame FillGrazingGaps(const DepthFrame& frame, const std::vector<float>& incidence_cos,
                           int reach_px, std::uint16_t min_mm) {
  DepthFrame filled = frame;
  if (reach_px <= 0 || !frame.Valid() || incidence_cos.size() != frame.depth_mm.size()) {
    return filled;
  }
  constexpr std::uint16_t kNone = std::numeric_limits<std::uint16_t>::max();
  cv::Mat grazing(frame.height, frame.width, CV_16UC1, cv::Scalar(kNone));
  bool any = false;
  for (int v = 0; v < frame.height; ++v) {
    auto* row = grazing.ptr<std::uint16_t>(v);
    for (int u = 0; u < frame.width; ++u) {
      const std::uint16_t d = frame.At(u, v);
      if (d >= min_mm && incidence_cos[v * frame.width + u] < kGrazingCos) {
        row[u] = d;
        any = true;
      }
    }
  }
  if (!any) return filled;
  cv::erode(grazing, grazing,
            cv::getStructuringElement(cv::MORPH_RECT,
                                      cv::Size(2 * reach_px + 1, 2 * reach_px + 1)),
            cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(kNone));
  for (int v = 0; v < frame.height; ++v) {
    const auto* row = grazing.ptr<std::uint16_t>(v);
    for (int u = 0; u < frame.width; ++u) {
      std::uint16_t& d = filled.depth_mm[static_cast<std::size_t>(v * frame.width + u)];
      if (d == 0 && row[u] != kNone) d = row[u];
    }
  }
  return filled;
}

}  // namespace dynamap::robotio
