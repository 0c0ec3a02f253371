#include "dynamap/calibration/SensorMotion.hpp"

#include <pcl/console/print.h>
#include <pcl/features/normal_3d.h>
#include <pcl/filters/voxel_grid.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/icp.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <memory>

#include "dynamap/mapping/FlannPointSearch.hpp"

namespace dynamap::calibration {
namespace {

using NormalCloud = pcl::PointCloud<pcl::PointNormal>;

NormalCloud::Ptr ToPcl(const PreparedCloud& cloud) {
  NormalCloud::Ptr out(new NormalCloud);
  out->resize(cloud.points.size());
  for (std::size_t i = 0; i < cloud.points.size(); ++i) {
    (*out)[i].getVector3fMap() = cloud.points[i];
    (*out)[i].getNormalVector3fMap() = cloud.normals[i];
  }
  return out;
}

}  // namespace

PreparedCloud PrepareCloud(const robotio::PointList& points, const IcpConfig& config) {
  pcl::PointCloud<pcl::PointXYZ>::Ptr raw(new pcl::PointCloud<pcl::PointXYZ>);
  raw->reserve(points.size());
  for (const Eigen::Vector3f& p : points) {
    if (p.allFinite()) raw->emplace_back(p.x(), p.y(), p.z());
  }
  pcl::PointCloud<pcl::PointXYZ>::Ptr down(new pcl::PointCloud<pcl::PointXYZ>);
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(raw);
  const auto leaf = static_cast<float>(config.voxel_m);
  grid.setLeafSize(leaf, leaf, leaf);
  grid.filter(*down);

  pcl::PointCloud<pcl::Normal> normals;
  pcl::NormalEstimation<pcl::PointXYZ, pcl::Normal> estimation;
  estimation.setInputCloud(down);
  // Not PCL's own tree: a system call per query with Debian's FLANN (FlannPointSearch.hpp).
  estimation.setSearchMethod(std::make_shared<mapping::FlannPointSearch<pcl::PointXYZ>>());
  estimation.setRadiusSearch(config.normal_radius_m);
  // Normals face the sensor at the origin, so both frames of a pair agree on their sign.
  estimation.setViewPoint(0.0f, 0.0f, 0.0f);
  estimation.compute(normals);

  PreparedCloud out;
  for (std::size_t i = 0; i < down->size(); ++i) {
    const Eigen::Vector3f n = normals[i].getNormalVector3fMap();
    if (!n.allFinite()) continue;  // Too few neighbours for a surface.
    out.points.push_back((*down)[i].getVector3fMap());
    out.normals.push_back(n);
  }
  return out;
}

SensorMotionResult EstimateSensorMotion(const PreparedCloud& from, const PreparedCloud& to,
                                        const Eigen::Isometry3d& guess, const IcpConfig& config) {
  SensorMotionResult result;
  if (static_cast<int>(from.points.size()) < config.min_correspondences ||
      static_cast<int>(to.points.size()) < config.min_correspondences) {
    return result;
  }
  // A pair without enough correspondences is told by the result; PCL would also print an
  // error line for it through the progress line.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  const NormalCloud::Ptr target = ToPcl(from);
  const NormalCloud::Ptr source = ToPcl(to);
  pcl::IterativeClosestPointWithNormals<pcl::PointNormal, pcl::PointNormal> icp;
  icp.setInputSource(source);
  icp.setInputTarget(target);
  icp.setSearchMethodTarget(std::make_shared<mapping::FlannPointSearch<pcl::PointNormal>>());
  icp.setMaxCorrespondenceDistance(config.max_correspondence_m);
  icp.setMaximumIterations(config.max_iterations);
  icp.setTransformationEpsilon(1e-10);
  icp.setEuclideanFitnessEpsilon(1e-10);
  NormalCloud aligned;
  icp.align(aligned, guess.matrix().cast<float>());
  if (!icp.hasConverged()) return result;
  if (config.fine_correspondence_m > 0.0) {
    // Near the solution, pairings as far as the wide first stage allows mostly join points
    // to the wrong surface (where one frame sees what the other does not) and pull the
    // motion towards them; a narrow second stage leaves them out.
    const Eigen::Matrix4f coarse = icp.getFinalTransformation();
    icp.setMaxCorrespondenceDistance(config.fine_correspondence_m);
    icp.align(aligned, coarse);
    if (!icp.hasConverged()) return result;
  }
  result.T_from_to.matrix() = icp.getFinalTransformation().cast<double>();

  // Point-to-plane information of the final pairing: its weakest direction is the motion
  // the scene cannot pin down.
  mapping::FlannPointSearch<pcl::PointNormal> tree;
  tree.setInputCloud(target);
  Eigen::Matrix<double, 6, 6> H = Eigen::Matrix<double, 6, 6>::Zero();
  double sum_sq = 0.0;
  double lever_sq = 0.0;
  std::vector<int> index(1);
  std::vector<float> dist_sq(1);
  const double pairing_m =
      config.fine_correspondence_m > 0.0 ? config.fine_correspondence_m : config.max_correspondence_m;
  const double max_sq = pairing_m * pairing_m;
  for (const pcl::PointNormal& p : aligned) {
    if (tree.nearestKSearch(p, 1, index, dist_sq) != 1 || dist_sq[0] > max_sq) continue;
    const pcl::PointNormal& q = (*target)[index[0]];
    const Eigen::Vector3d pp = p.getVector3fMap().cast<double>();
    const Eigen::Vector3d n = q.getNormalVector3fMap().cast<double>();
    const double e = n.dot(pp - q.getVector3fMap().cast<double>());
    Eigen::Matrix<double, 6, 1> J;
    J << pp.cross(n), n;
    H += J * J.transpose();
    sum_sq += e * e;
    lever_sq += pp.squaredNorm();
    ++result.correspondences;
  }
  if (result.correspondences < config.min_correspondences) return result;
  // Rotation rows scaled by the mean lever so both blocks are in metres.
  const double lever = std::sqrt(lever_sq / result.correspondences);
  Eigen::Matrix<double, 6, 1> scale;
  scale << 1.0 / lever, 1.0 / lever, 1.0 / lever, 1.0, 1.0, 1.0;
  const Eigen::Matrix<double, 6, 6> Hs = scale.asDiagonal() * H * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(Hs);
  const double largest = eigen.eigenvalues()(5);
  result.structure = largest > 0.0 ? eigen.eigenvalues()(0) / largest : 0.0;
  if (largest > 0.0) result.information = Hs / largest;
  result.lever_m = lever;
  result.rms_m = std::sqrt(sum_sq / result.correspondences);
  result.accepted = result.rms_m <= config.max_rms_m && result.structure >= config.min_structure;
  return result;
}

}  // namespace dynamap::calibration
