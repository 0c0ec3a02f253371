#include "SyntheticScene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace dynamap::mapping::testing {
namespace {

// Ray parameter of the surface hit and the axis of that surface's normal.
struct Hit {
  float t = std::numeric_limits<float>::max();
  int normal_axis = 0;
};

Hit HitBox(const Box& box, const Eigen::Vector3f& o, const Eigen::Vector3f& d) {
  float t_near = 0.0f, t_far = std::numeric_limits<float>::max();
  int near_axis = 0;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-9f) {
      if (o[a] < box.min[a] || o[a] > box.max[a]) return {};
      continue;
    }
    float t0 = (box.min[a] - o[a]) / d[a], t1 = (box.max[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_near) {
      t_near = t0;
      near_axis = a;
    }
    t_far = std::min(t_far, t1);
  }
  if (t_near <= t_far && t_near > 0.0f) return {t_near, near_axis};
  return {};
}

// The nearest surface along o + t d, t = max() when none.
Hit NearestHit(const SyntheticScene& scene, const Eigen::Vector3f& o, const Eigen::Vector3f& d) {
  Hit nearest;
  if (d.x() > 1e-6f) nearest = {(scene.wall_x - o.x()) / d.x(), 0};
  if (d.z() < -1e-6f && (scene.floor_z - o.z()) / d.z() < nearest.t) {
    nearest = {(scene.floor_z - o.z()) / d.z(), 2};
  }
  for (const Box& box : scene.boxes) {
    const Hit hit = HitBox(box, o, d);
    if (hit.t < nearest.t) nearest = hit;
  }
  return nearest;
}

float Nearest(const SyntheticScene& scene, const Eigen::Vector3f& o, const Eigen::Vector3f& d) {
  return NearestHit(scene, o, d).t;
}

}  // namespace

robotio::DepthFrame RenderDepth(const SyntheticScene& scene, const Eigen::Vector3f& origin,
                                float yaw, const robotio::Intrinsics& intrinsics) {
  robotio::DepthFrame frame;
  frame.width = intrinsics.width;
  frame.height = intrinsics.height;
  frame.intrinsics = intrinsics;
  frame.depth_mm.assign(static_cast<std::size_t>(frame.width) * frame.height, 0);
  const Eigen::Matrix3f R = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
                             robotio::BodyFromOptical())
                                .cast<float>();
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      // With the optical z component 1, the ray parameter is the z-depth.
      const Eigen::Vector3f d =
          R * Eigen::Vector3f(static_cast<float>((u - intrinsics.cx) / intrinsics.fx),
                              static_cast<float>((v - intrinsics.cy) / intrinsics.fy), 1.0f);
      const Hit hit = NearestHit(scene, origin, d);
      const float t = hit.t;
      if (std::abs(d[hit.normal_axis]) < scene.drop_below_incidence_cos * d.norm()) continue;
      if (t < 60.0f) {
        frame.depth_mm[v * frame.width + u] = static_cast<std::uint16_t>(std::lround(t * 1000.0f));
      }
    }
  }
  return frame;
}

robotio::KinectMount LevelMount(const robotio::Intrinsics& intrinsics) {
  robotio::KinectMount mount;
  mount.intrinsics = intrinsics;
  mount.T_base_kinect.linear() = robotio::BodyFromOptical();
  mount.min_range_m = 0.3;
  mount.max_range_m = 8.0;
  return mount;
}

Eigen::Isometry3d BasePose(const Eigen::Vector3f& origin, float yaw) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = origin.cast<double>();
  T.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return T;
}

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
      const float t = Nearest(scene, origin, d);
      const bool hit = t <= max_range;
      rays.ends.push_back(origin + d * (hit ? t : max_range));
      rays.hit.push_back(hit);
    }
  }
  return rays;
}

}  // namespace dynamap::mapping::testing
