#include "dynamap/planning/FieldOfView.hpp"

namespace dynamap::planning {

FieldOfView::FieldOfView(const robotio::Rig& rig, double min_height_m, double max_height_m) {
  for (const robotio::KinectMount& mount : rig.kinects) {
    cameras_.push_back({mount.T_base_kinect.inverse(), mount});
  }
  constexpr int kHeights = 5;  // Every 0.225 m of the default band.
  for (int i = 0; i < kHeights; ++i) {
    heights_.push_back(min_height_m + (max_height_m - min_height_m) * i / (kHeights - 1));
  }
}

bool FieldOfView::Sees(const Eigen::Vector2d& p_base, double margin_px, double margin_m) const {
  for (const Camera& camera : cameras_) {
    const robotio::Intrinsics& k = camera.mount.intrinsics;
    for (const double z : heights_) {
      const Eigen::Vector3d p = camera.T_kinect_base * Eigen::Vector3d(p_base.x(), p_base.y(), z);
      if (p.z() < camera.mount.min_range_m + margin_m ||
          p.z() > camera.mount.max_range_m - margin_m) {
        continue;
      }
      const double u = k.fx * p.x() / p.z() + k.cx;
      const double v = k.fy * p.y() / p.z() + k.cy;
      if (u >= margin_px && u <= k.width - 1 - margin_px && v >= margin_px &&
          v <= k.height - 1 - margin_px) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace dynamap::planning
