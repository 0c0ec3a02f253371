// The surfaces a mission's Kinects hit from within the inspection distance, kept as voxels
// for the report's surface coverage (scored against the simulator's true surfaces).
#pragma once

#include <Eigen/Geometry>

#include <cstdint>
#include <unordered_set>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::app::runtime {

class InspectedSurfaces {
 public:
  InspectedSurfaces(double resolution_m, double inspection_distance_m);

  // Marks the voxels `depth` hit within the inspection distance of the Kinect, seen from
  // `T_world_base` (a sample of about 160 rays per image row).
  void Add(const robotio::DepthFrame& depth, const robotio::KinectMount& mount,
           const Eigen::Isometry3d& T_world_base);
  // A hit marked in the voxel of `p` or one of its 26 neighbours.
  [[nodiscard]] bool Contains(const Eigen::Vector3f& p) const;

 private:
  [[nodiscard]] std::uint64_t VoxelId(const Eigen::Vector3f& p) const;

  double resolution_m_;
  double inspection_distance_m_;
  std::unordered_set<std::uint64_t> voxels_;
};

}  // namespace dynamap::app::runtime
