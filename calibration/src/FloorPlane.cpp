#include "dynamap/calibration/FloorPlane.hpp"

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/sample_consensus/ransac.h>
#include <pcl/sample_consensus/sac_model_perpendicular_plane.h>
#include <pcl/sample_consensus/sac_model_plane.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace dynamap::calibration {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

Cloud::Ptr ToCloud(const robotio::PointList& points) {
  Cloud::Ptr cloud(new Cloud);
  cloud->points.reserve(points.size());
  for (const Eigen::Vector3f& p : points) {
    if (p.allFinite()) cloud->points.emplace_back(p.x(), p.y(), p.z());
  }
  cloud->width = static_cast<std::uint32_t>(cloud->points.size());
  cloud->height = 1;
  cloud->is_dense = true;
  return cloud;
}

// 1.4826 × the median absolute point-plane distance: the noise sigma of the floor points,
// unmoved by the minority of non-floor points in the band.
double RobustSpread(const Cloud& cloud, const pcl::Indices& inliers,
                    const Eigen::VectorXf& plane) {
  std::vector<double> distances;
  distances.reserve(inliers.size());
  const Eigen::Vector3f n = plane.head<3>();
  const float norm = n.norm();
  for (const auto index : inliers) {
    distances.push_back(std::abs(n.dot(cloud[index].getVector3fMap()) + plane[3]) / norm);
  }
  if (distances.empty()) return 0.0;
  auto middle = distances.begin() + static_cast<std::ptrdiff_t>(distances.size() / 2);
  std::nth_element(distances.begin(), middle, distances.end());
  return 1.4826 * *middle;
}

}  // namespace

PlaneFit FitPlane(const robotio::PointList& points, const PlaneFitConfig& config,
                  const std::optional<Eigen::Vector3d>& expected_normal) {
  PlaneFit fit;
  const Cloud::Ptr cloud = ToCloud(points);
  fit.points = cloud->size();
  if (cloud->size() < 3) return fit;

  pcl::SampleConsensusModelPlane<pcl::PointXYZ>::Ptr model;
  if (expected_normal) {
    // Only planes near the expected orientation count, so a large wall cannot win.
    auto perpendicular =
        std::make_shared<pcl::SampleConsensusModelPerpendicularPlane<pcl::PointXYZ>>(cloud);
    perpendicular->setAxis(expected_normal->cast<float>());
    perpendicular->setEpsAngle(config.max_normal_deviation_rad);
    model = perpendicular;
  } else {
    model = std::make_shared<pcl::SampleConsensusModelPlane<pcl::PointXYZ>>(cloud);
  }
  pcl::RandomSampleConsensus<pcl::PointXYZ> ransac(model, config.distance_threshold_m);
  ransac.setMaxIterations(config.max_iterations);
  ransac.setProbability(config.probability);
  if (!ransac.computeModel()) return fit;

  pcl::Indices inliers;
  ransac.getInliers(inliers);
  Eigen::VectorXf coefficients;
  ransac.getModelCoefficients(coefficients);
  if (inliers.size() < 3 || coefficients.size() != 4) return fit;
  if (config.refine) {
    Eigen::VectorXf refined;
    model->optimizeModelCoefficients(inliers, coefficients, refined);
    if (refined.size() == 4 && refined.allFinite()) {
      coefficients = refined;
      // The refit plane may gather a slightly different inlier set.
      model->selectWithinDistance(coefficients, config.distance_threshold_m, inliers);
    }
    // The wide RANSAC band also takes the feet of walls and furniture (up to the band
    // height above the floor), which lift the plane where they stand. Narrowing the band
    // to a few times the inliers' own spread and refitting leaves them out.
    for (int round = 0; round < config.narrowing_rounds; ++round) {
      const double spread = RobustSpread(*cloud, inliers, coefficients);
      const double band = std::clamp(config.narrowing_sigmas * spread, config.min_band_m,
                                     config.distance_threshold_m);
      pcl::Indices narrowed;
      model->selectWithinDistance(coefficients, band, narrowed);
      if (narrowed.size() < 3) break;
      model->optimizeModelCoefficients(narrowed, coefficients, refined);
      if (refined.size() != 4 || !refined.allFinite()) break;
      coefficients = refined;
      inliers = std::move(narrowed);
    }
  }

  Eigen::Vector3d n = coefficients.head<3>().cast<double>();
  double d = coefficients[3];
  const double norm = n.norm();
  if (norm <= 0.0 || inliers.size() < 3) return fit;
  n /= norm;
  d /= norm;
  if (d < 0.0) {
    n = -n;
    d = -d;
  }
  double sum_sq = 0.0;
  for (const auto index : inliers) {
    const Eigen::Vector3d p = (*cloud)[index].getVector3fMap().cast<double>();
    const double e = n.dot(p) + d;
    sum_sq += e * e;
  }
  fit.ok = true;
  fit.normal = n;
  fit.distance_m = d;
  fit.inliers = inliers.size();
  fit.inlier_share = static_cast<double>(fit.inliers) / static_cast<double>(fit.points);
  fit.rms_m = std::sqrt(sum_sq / static_cast<double>(fit.inliers));
  return fit;
}

Eigen::Vector3d FloorNormalInKinect(const Eigen::Isometry3d& T_base_kinect) {
  return T_base_kinect.linear().transpose() * Eigen::Vector3d::UnitZ();
}

FloorPose FloorPoseFromPlane(const PlaneFit& plane) {
  // The floor normal (base z) in the body frame is row 2 of R_base_body, which for
  // Rz(yaw)·Ry(pitch)·Rx(roll) is (-sin p, cos p sin r, cos p cos r) whatever the yaw.
  const Eigen::Vector3d n_body = robotio::BodyFromOptical() * plane.normal;
  FloorPose pose;
  pose.pitch_rad = std::asin(std::clamp(-n_body.x(), -1.0, 1.0));
  pose.roll_rad = std::atan2(n_body.y(), n_body.z());
  // The sensor is on the side the normal points to, at the plane distance: its height.
  pose.height_m = plane.distance_m;
  pose.inlier_share = plane.inlier_share;
  pose.rms_m = plane.rms_m;
  pose.frames = plane.ok ? 1 : 0;
  return pose;
}

FloorPose CombineFloorFits(const std::vector<PlaneFit>& fits) {
  PlaneFit mean;
  Eigen::Vector3d normal_sum = Eigen::Vector3d::Zero();
  double distance_sum = 0.0;
  double share_sum = 0.0;
  double rms_sum = 0.0;
  int count = 0;
  for (const PlaneFit& fit : fits) {
    if (!fit.ok) continue;
    normal_sum += fit.normal;
    distance_sum += fit.distance_m;
    share_sum += fit.inlier_share;
    rms_sum += fit.rms_m;
    ++count;
  }
  if (count == 0) return FloorPose{};
  mean.ok = true;
  mean.normal = normal_sum.normalized();
  mean.distance_m = distance_sum / count;
  mean.inlier_share = share_sum / count;
  mean.rms_m = rms_sum / count;
  FloorPose pose = FloorPoseFromPlane(mean);
  pose.frames = count;
  return pose;
}

}  // namespace dynamap::calibration
