#include "SyntheticScene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynamap::mapping::testing {
namespace {

float HitBox(const Box& box, const Eigen::Vector3f& o, const Eigen::Vector3f& d) {
  float t_near = 0.0f, t_far = std::numeric_limits<float>::max();
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-9f) {
      if (o[a] < box.min[a] || o[a] > box.max[a]) return std::numeric_limits<float>::max();
      continue;
    }
    float t0 = (box.min[a] - o[a]) / d[a], t1 = (box.max[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    t_near = std::max(t_near, t0);
    t_far = std::min(t_far, t1);
  }
  return t_near <= t_far && t_near > 0.0f ? t_near : std::numeric_limits<float>::max();
}

}  // namespace

robotio::DepthRays CastScan(const SyntheticScene& scene, const Eigen::Vector3f& origin,
                            float max_range, float step_deg) {
  robotio::DepthRays rays;
  rays.origin = origin;
  constexpr float kDeg = 3.14159265f / 180.0f;
  for (float pitch = -25.0f; pitch <= 20.0f; pitch += step_deg) {
    for (float yaw = -30.0f; yaw <= 30.0f; yaw += step_deg) {
      const Eigen::Vector3f d(std::cos(pitch * kDeg) * std::cos(yaw * kDeg),
                              std::cos(pitch * kDeg) * std::sin(yaw * kDeg),
                              std::sin(pitch * kDeg));
      float t = std::numeric_limits<float>::max();
      if (d.x() > 1e-6f) t = std::min(t, (scene.wall_x - origin.x()) / d.x());
      if (d.z() < -1e-6f) t = std::min(t, (scene.floor_z - origin.z()) / d.z());
      for (const Box& box : scene.boxes) t = std::min(t, HitBox(box, origin, d));
      const bool hit = t <= max_range;
      rays.ends.push_back(origin + d * (hit ? t : max_range));
      rays.hit.push_back(hit);
    }
  }
  return rays;
}

}  // namespace dynamap::mapping::testing
