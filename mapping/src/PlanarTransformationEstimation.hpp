// Planar (x, y, yaw) rigid transform from ICP correspondences, point-to-point in closed
// form or point-to-plane linearised: the base moves in a plane (thesis 5.2), so z, roll
// and pitch are left to the calibration. Private to the registration module.
#pragma once

#include <pcl/point_types.h>
#include <pcl/registration/transformation_estimation.h>

namespace dynamap::mapping::internal {

class PlanarTransformationEstimation
    : public pcl::registration::TransformationEstimation<pcl::PointNormal, pcl::PointNormal,
                                                         float> {
 public:
  using Cloud = pcl::PointCloud<pcl::PointNormal>;

  explicit PlanarTransformationEstimation(bool point_to_plane) : point_to_plane_(point_to_plane) {}

  void estimateRigidTransformation(const Cloud& src, const Cloud& tgt,
                                   Matrix4& T) const override;
  void estimateRigidTransformation(const Cloud& src, const pcl::Indices& indices_src,
                                   const Cloud& tgt, Matrix4& T) const override;
  void estimateRigidTransformation(const Cloud& src, const pcl::Indices& indices_src,
                                   const Cloud& tgt, const pcl::Indices& indices_tgt,
                                   Matrix4& T) const override;
  void estimateRigidTransformation(const Cloud& src, const Cloud& tgt,
                                   const pcl::Correspondences& correspondences,
                                   Matrix4& T) const override;

 private:
  // Pairs (source point, target point) given by index callbacks.
  template <typename PairAt>
  void Estimate(std::size_t count, const PairAt& pair_at, Matrix4& T) const;

  bool point_to_plane_;
};

}  // namespace dynamap::mapping::internal
