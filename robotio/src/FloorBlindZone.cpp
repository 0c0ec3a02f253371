#include "dynamap/robotio/FloorBlindZone.hpp"

#include <algorithm>
#include <array>
#include <limits>

namespace dynamap::robotio {

namespace {

// Horizontal distances of the floor points seen along one image edge; empty when a ray of
// the edge misses the floor within range (then the edge is not the one nearest the robot).
std::vector<double> EdgeFloorDistances(const KinectMount& k, int edge) {
  const Intrinsics& in = k.intrinsics;
  const int n = edge < 2 ? in.width : in.height;
  const int step = std::max(1, n / 64);
  std::vector<double> distances;
  for (int i = 0; i < n; i += step) {
    double u = i;
    double v = i;
    switch (edge) {
      case 0: v = 0; break;                 // Top row.
      case 1: v = in.height - 1; break;     // Bottom row.
      case 2: u = 0; break;                 // Left column.
      default: u = in.width - 1; break;     // Right column.
    }
    const Eigen::Vector3d ray_optical((u - in.cx) / in.fx, (v - in.cy) / in.fy, 1.0);
    const Eigen::Vector3d origin = k.T_base_kinect.translation();
    const Eigen::Vector3d ray = k.T_base_kinect.linear() * ray_optical;
    if (ray.z() >= 0.0 || origin.z() <= 0.0) return {};
    const double t = -origin.z() / ray.z();  // Depth along optical z is t (ray_optical.z = 1).
    if (t < k.min_range_m || t > k.max_range_m) return {};
    const Eigen::Vector3d floor = origin + t * ray;
    distances.push_back(floor.head<2>().norm());
  }
  return distances;
}

}  // namespace

double FloorBlindRadius(const Rig& rig) {
  double radius = 0.0;
  for (const KinectMount& k : rig.kinects) {
    double nearest_edge_mean = std::numeric_limits<double>::infinity();
    double nearest_edge_max = 0.0;
    for (int edge = 0; edge < 4; ++edge) {
      const std::vector<double> d = EdgeFloorDistances(k, edge);
      if (d.empty()) continue;
      double sum = 0.0;
      for (const double x : d) sum += x;
      const double mean = sum / static_cast<double>(d.size());
      if (mean < nearest_edge_mean) {
        nearest_edge_mean = mean;
        nearest_edge_max = *std::max_element(d.begin(), d.end());
      }
    }
    radius = std::max(radius, nearest_edge_max);
  }
  return radius;
}

}  // namespace dynamap::robotio
