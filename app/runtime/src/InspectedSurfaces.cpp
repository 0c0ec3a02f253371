#include "dynamap/app/runtime/InspectedSurfaces.hpp"

#include <cmath>

namespace dynamap::app::runtime {

InspectedSurfaces::InspectedSurfaces(double resolution_m, double inspection_distance_m)
    : resolution_m_(resolution_m), inspection_distance_m_(inspection_distance_m) {}

std::uint64_t InspectedSurfaces::VoxelId(const Eigen::Vector3f& p) const {
  const double r = resolution_m_;
  const auto pack = [r](float v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(v / r)) + (1 << 20)) &
           0x1fffff;
  };
  return pack(p.x()) | (pack(p.y()) << 21) | (pack(p.z()) << 42);
}

void InspectedSurfaces::Add(const robotio::DepthRays& rays) {
  for (std::size_t i = 0; i < rays.ends.size(); ++i) {
    if (rays.hit[i] && (rays.ends[i] - rays.origin).norm() <= inspection_distance_m_) {
      voxels_.insert(VoxelId(rays.ends[i]));
    }
  }
}

bool InspectedSurfaces::Contains(const Eigen::Vector3f& p) const {
  const auto r = static_cast<float>(resolution_m_);
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dz = -1; dz <= 1; ++dz) {
        if (voxels_.count(VoxelId(p + Eigen::Vector3f(dx * r, dy * r, dz * r)))) return true;
      }
    }
  }
  return false;
}

}  // namespace dynamap::app::runtime
