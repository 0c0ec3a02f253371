#include "dynamap/robotio/DepthProjection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "dynamap/robotio/DepthEdges.hpp"

namespace dynamap::robotio {

PointList DepthToOrganizedPoints(const DepthFrame& frame) {
  const Intrinsics& k = frame.intrinsics;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  PointList points(frame.depth_mm.size(), Eigen::Vector3f(nan, nan, nan));
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const std::uint16_t d = frame.At(u, v);
      if (d == 0) continue;
      const float z = static_cast<float>(d) * 0.001f;
      points[v * frame.width + u] =
          Eigen::Vector3f(static_cast<float>((u - k.cx) / k.fx) * z,
                          static_cast<float>((v - k.cy) / k.fy) * z, z);
    }
  }
  return points;
}

PointList DepthToPoints(const DepthFrame& frame, double min_range_m, double max_range_m) {
  const Intrinsics& k = frame.intrinsics;
  const auto min_mm = static_cast<std::uint16_t>(std::max(1.0, min_range_m * 1000.0));
  const double max_mm = max_range_m * 1000.0;
  PointList points;
  points.reserve(frame.depth_mm.size());
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const std::uint16_t d = frame.At(u, v);
      if (d < min_mm || d > max_mm) continue;
      const float z = static_cast<float>(d) * 0.001f;
      points.emplace_back(static_cast<float>((u - k.cx) / k.fx) * z,
                          static_cast<float>((v - k.cy) / k.fy) * z, z);
    }
  }
  return points;
}

PointList DepthToBasePoints(const DepthFrame& frame, const KinectMount& mount) {
  PointList points = DepthToPoints(frame, mount.min_range_m, mount.max_range_m);
  const Eigen::Isometry3f T = mount.T_base_kinect.cast<float>();
  for (Eigen::Vector3f& p : points) p = T * p;
  return points;
}

namespace {

// Point of pixel (u, v) in the optical frame; nullopt outside the image or the range.
std::optional<Eigen::Vector3f> PixelPoint(const DepthFrame& frame, int u, int v,
                                          std::uint16_t min_mm, double max_mm) {
  if (u < 0 || v < 0 || u >= frame.width || v >= frame.height) return std::nullopt;
  const std::uint16_t d = frame.At(u, v);
  if (d < min_mm || d > max_mm) return std::nullopt;
  const Intrinsics& k = frame.intrinsics;
  const float z = static_cast<float>(d) * 0.001f;
  return Eigen::Vector3f(static_cast<float>((u - k.cx) / k.fx) * z,
                         static_cast<float>((v - k.cy) / k.fy) * z, z);
}

// Depth limit that lets every measurement through (the neighbours of a ray cut at max
// range lie beyond it too).
constexpr double kAnyRangeMm = 65535.0;

// Surface tangent at `p` along one image axis, towards the neighbour nearer in depth (the
// other one may lie across a depth edge).
std::optional<Eigen::Vector3f> Tangent(const Eigen::Vector3f& p,
                                       const std::optional<Eigen::Vector3f>& before,
                                       const std::optional<Eigen::Vector3f>& after) {
  if (before && (!after || std::abs(before->z() - p.z()) <= std::abs(after->z() - p.z()))) {
    return p - *before;
  }
  if (after) return *after - p;
  return std::nullopt;
}

// |cos| of the angle between the ray to p and the surface normal from the four
// neighbouring pixels; 0 when they do not give a normal (the Kinect drops pixels at
// grazing incidence, so a missing neighbour is most often a grazing surface).
float IncidenceCos(const DepthFrame& frame, int u, int v, const Eigen::Vector3f& p,
                   std::uint16_t min_mm, double max_mm) {
  const auto tu = Tangent(p, PixelPoint(frame, u - 1, v, min_mm, max_mm),
                          PixelPoint(frame, u + 1, v, min_mm, max_mm));
  const auto tv = Tangent(p, PixelPoint(frame, u, v - 1, min_mm, max_mm),
                          PixelPoint(frame, u, v + 1, min_mm, max_mm));
  if (!tu || !tv) return 0.0f;
  const Eigen::Vector3f n = tu->cross(*tv);
  const float scale = n.norm() * p.norm();
  return scale > 0.0f ? std::abs(n.dot(p)) / scale : 0.0f;
}

}  // namespace

DepthRays DepthToRays(const DepthFrame& frame, const KinectMount& mount,
                      const Eigen::Isometry3d& T_target_base, int stride,
                      const EdgeClearance& edges) {
  const Intrinsics& k = frame.intrinsics;
  const Eigen::Isometry3f T = (T_target_base * mount.T_base_kinect).cast<float>();
  DepthRays rays;
  rays.origin = T.translation();
  const auto min_mm = static_cast<std::uint16_t>(std::max(1.0, mount.min_range_m * 1000.0));
  const double max_mm = mount.max_range_m * 1000.0;
  const float max_z = static_cast<float>(mount.max_range_m);
  const auto direction_of = [&k](int u, int v) {
    return Eigen::Vector3f(static_cast<float>((u - k.cx) / k.fx),
                           static_cast<float>((v - k.cy) / k.fy), 1.0f);
  };
  // Incidence of every measured pixel; a ray cut at max range carries the incidence of the
  // surface it measured beyond. The gaps beside grazing pixels need every pixel's.
  const bool fill_gaps = edges.lateral_m > 0.0 && edges.grazing_gap_px > 0;
  const int step = fill_gaps ? 1 : stride;
  std::vector<float> incidence(frame.depth_mm.size(), 0.0f);
  // What FillGrazingGaps reads: the incidence of the pixels that may seed a gap, those at
  // least gap_min_height_m high; the others count as head-on.
  const auto gap_min_height = static_cast<float>(edges.gap_min_height_m);
  std::vector<float> seed_incidence(fill_gaps ? frame.depth_mm.size() : 0, 1.0f);
  for (int v = 0; v < frame.height; v += step) {
    for (int u = 0; u < frame.width; u += step) {
      const std::uint16_t d = frame.At(u, v);
      if (d < min_mm) continue;
      const Eigen::Vector3f p = direction_of(u, v) * (static_cast<float>(d) * 0.001f);
      const std::size_t i = static_cast<std::size_t>(v * frame.width + u);
      incidence[i] = IncidenceCos(frame, u, v, p, min_mm, d <= max_mm ? max_mm : kAnyRangeMm);
      if (fill_gaps && (T * p).z() >= gap_min_height) seed_incidence[i] = incidence[i];
    }
  }
  std::vector<float> alongside;
  if (edges.lateral_m > 0.0) {
    // Only a filled image is a copy; otherwise the frame is read as it is.
    const std::optional<DepthFrame> filled =
        fill_gaps ? std::optional<DepthFrame>(
                        FillGrazingGaps(frame, seed_incidence, edges.grazing_gap_px, min_mm))
                  : std::nullopt;
    alongside = NearestDepthAlongside(filled ? *filled : frame, edges.lateral_m, min_mm,
                                      edges.side_depth_m);
  }
  const std::size_t most = static_cast<std::size_t>((frame.width + stride - 1) / stride) *
                          static_cast<std::size_t>((frame.height + stride - 1) / stride);
  rays.ends.reserve(most);
  rays.hit.reserve(most);
  rays.incidence_cos.reserve(most);
  rays.surface_range_m.reserve(most);
  if (!alongside.empty()) rays.alongside_range_m.reserve(most);
  for (int v = 0; v < frame.height; v += stride) {
    for (int u = 0; u < frame.width; u += stride) {
      const std::uint16_t d = frame.At(u, v);
      if (d < min_mm) continue;
      const bool hit = d <= max_mm;
      const Eigen::Vector3f direction = direction_of(u, v);
      // Beyond max range: free space up to the max-range depth, no endpoint. The cut is at
      // the same depth as the farthest hit, so every voxel a hit can reach is one a longer
      // ray sees free (a cut at that range along the ray left a shell beside the image axis
      // that was only ever hit: whatever passed through it stayed in the map).
      const float measured_z = static_cast<float>(d) * 0.001f;
      const float z = hit ? measured_z : max_z;
      rays.ends.push_back(T * (direction * z));
      rays.hit.push_back(hit);
      rays.incidence_cos.push_back(incidence[v * frame.width + u]);
      rays.surface_range_m.push_back(measured_z * direction.norm());
      if (!alongside.empty()) {
        rays.alongside_range_m.push_back(alongside[v * frame.width + u] * direction.norm());
      }
    }
  }
  return rays;
}

}  // namespace dynamap::robotio
