#include "PlanarTransformationEstimation.hpp"

#include <Eigen/Cholesky>
#include <cmath>

namespace dynamap::mapping::internal {

template <typename PairAt>
void PlanarTransformationEstimation::Estimate(std::size_t count, const PairAt& pair_at,
                                              Matrix4& T) const {
  T.setIdentity();
  double yaw = 0.0;
  Eigen::Vector2d t = Eigen::Vector2d::Zero();
  if (point_to_plane_) {
    // Residual n·(R p + t − q) linearised in (tx, ty, yaw): the Jacobian row is
    // [nx, ny, nx·(−py) + ny·px]; one Gauss-Newton step per ICP iteration.
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < count; ++i) {
      const auto [p, q] = pair_at(i);
      const Eigen::Vector3d n = q.getNormalVector3fMap().template cast<double>();
      if (!n.allFinite()) continue;
      const Eigen::Vector3d ps = p.getVector3fMap().template cast<double>();
      const Eigen::Vector3d qs = q.getVector3fMap().template cast<double>();
      const Eigen::Vector3d J(n.x(), n.y(), -n.x() * ps.y() + n.y() * ps.x());
      const double r = n.dot(ps - qs);
      A += J * J.transpose();
      b -= J * r;
    }
    // A small damping keeps a degenerate scene (a bare corridor along x) from
    // producing a wild step along the unobservable direction.
    A.diagonal().array() += 1e-6 * (A.trace() / 3.0 + 1e-12);
    const Eigen::Vector3d x = A.ldlt().solve(b);
    if (x.allFinite()) {
      t = x.head<2>();
      yaw = x.z();
    }
  } else {
    // Closed form in 2D: Procrustes on the demeaned x/y coordinates.
    Eigen::Vector2d mean_p = Eigen::Vector2d::Zero();
    Eigen::Vector2d mean_q = Eigen::Vector2d::Zero();
    for (std::size_t i = 0; i < count; ++i) {
      const auto [p, q] = pair_at(i);
      mean_p += Eigen::Vector2d(p.x, p.y);
      mean_q += Eigen::Vector2d(q.x, q.y);
    }
    if (count == 0) return;
    mean_p /= static_cast<double>(count);
    mean_q /= static_cast<double>(count);
    double sin_sum = 0.0;
    double cos_sum = 0.0;
    for (std::size_t i = 0; i < count; ++i) {
      const auto [p, q] = pair_at(i);
      const Eigen::Vector2d a = Eigen::Vector2d(p.x, p.y) - mean_p;
      const Eigen::Vector2d c = Eigen::Vector2d(q.x, q.y) - mean_q;
      sin_sum += a.x() * c.y() - a.y() * c.x();
      cos_sum += a.x() * c.x() + a.y() * c.y();
    }
    yaw = std::atan2(sin_sum, cos_sum);
    const Eigen::Rotation2Dd R(yaw);
    t = mean_q - R * mean_p;
  }
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  T.topLeftCorner<2, 2>() = R.cast<float>();
  T(0, 3) = static_cast<float>(t.x());
  T(1, 3) = static_cast<float>(t.y());
}

void PlanarTransformationEstimation::estimateRigidTransformation(const Cloud& src,
                                                                 const Cloud& tgt,
                                                                 Matrix4& T) const {
  const std::size_t n = std::min(src.size(), tgt.size());
  Estimate(n, [&](std::size_t i) { return std::make_pair(src[i], tgt[i]); }, T);
}

void PlanarTransformationEstimation::estimateRigidTransformation(
    const Cloud& src, const pcl::Indices& indices_src, const Cloud& tgt, Matrix4& T) const {
  const std::size_t n = std::min(indices_src.size(), tgt.size());
  Estimate(n, [&](std::size_t i) { return std::make_pair(src[indices_src[i]], tgt[i]); }, T);
}

void PlanarTransformationEstimation::estimateRigidTransformation(
    const Cloud& src, const pcl::Indices& indices_src, const Cloud& tgt,
    const pcl::Indices& indices_tgt, Matrix4& T) const {
  const std::size_t n = std::min(indices_src.size(), indices_tgt.size());
  Estimate(
      n, [&](std::size_t i) { return std::make_pair(src[indices_src[i]], tgt[indices_tgt[i]]); },
      T);
}

void PlanarTransformationEstimation::estimateRigidTransformation(
    const Cloud& src, const Cloud& tgt, const pcl::Correspondences& correspondences,
    Matrix4& T) const {
  Estimate(
      correspondences.size(),
      [&](std::size_t i) {
        const auto& c = correspondences[i];
        return std::make_pair(src[static_cast<std::size_t>(c.index_query)],
                              tgt[static_cast<std::size_t>(c.index_match)]);
      },
      T);
}

}  // namespace dynamap::mapping::internal
