// A small analytic scene for mapping tests: a wall, a floor and box-shaped people, seen by
// a fan of rays from a sensor origin (no simulator needed).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::mapping::testing {

struct Box {
  Eigen::Vector3f min;
  Eigen::Vector3f max;
};

struct SyntheticScene {
  float wall_x = 3.0f;     // Wall plane x = wall_x (m).
  float floor_z = -0.5f;   // Floor plane z = floor_z (m).
  std::vector<Box> boxes;  // People / furniture.
  // RenderDepth gives no depth where |cos| of the incidence is below this, as the Kinect
  // drops pixels that see a surface at grazing incidence (about 0.26, 75 deg); 0 = never.
  float drop_below_incidence_cos = 0.0f;
};

// Rays from `origin` over yaw [-30, 30] and pitch [-25, 20] degrees at `step_deg`; each
// ray ends at the nearest surface, or is cut at `max_range` with no hit.
robotio::DepthRays CastScan(const SyntheticScene& scene, const Eigen::Vector3f& origin,
                            float max_range, float step_deg = 0.5f);

// A level camera at `origin` looking along `yaw` (rad, about z): the scene as its depth
// image of `intrinsics` (z-depth in mm, 0 where nothing is hit).
robotio::DepthFrame RenderDepth(const SyntheticScene& scene, const Eigen::Vector3f& origin,
                                float yaw, const robotio::Intrinsics& intrinsics);
// The pose of that camera as RenderDepth's frame is inserted: a mount with the optical
// frame level and forward at the base, and the base at `origin` turned by `yaw`.
robotio::KinectMount LevelMount(const robotio::Intrinsics& intrinsics);
Eigen::Isometry3d BasePose(const Eigen::Vector3f& origin, float yaw);

}  // namespace dynamap::mapping::testing
