// The surfaces a mission's Kinects hit from within the inspection distance, kept as voxels
// for the report's surface coverage (scored against the simulator's true surfaces).
#pragma once

#include <Eigen/Core>

#include <cstdint>
#include <unordered_set>

#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::app::runtime {

class InspectedSurfaces {
 public:
  InspectedSurfaces(double resolution_m, double inspection_distance_m);

  // Marks the voxels a frame's rays (robotio::DepthToRays, placed where the Kinect was)
  // hit within the inspection distance of their origin.
  void Add(const robotio::DepthRays& rays);
  // A hit marked in the voxel of `p` or one of its 26 neighbours.
  [[nodiscard]] bool Contains(const Eigen::Vector3f& p) const;

 private:
  [[nodiscard]] std::uint64_t VoxelId(const Eigen::Vector3f& p) const;

  double resolution_m_;
  double inspection_distance_m_;
  std::unordered_set<std::uint64_t> voxels_;
};

}  // namespace dynamap::app::runtime
