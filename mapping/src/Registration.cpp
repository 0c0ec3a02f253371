#include "dynamap/mapping/Registration.hpp"

#include <Eigen/Eigenvalues>

#include <pcl/console/print.h>
#include <pcl/features/normal_3d.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/registration/correspondence_rejection_trimmed.h>
#include <pcl/registration/icp.h>
#include <pcl/registration/transformation_estimation_point_to_plane_lls.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "PlanarTransformationEstimation.hpp"
#include "dynamap/mapping/FlannPointSearch.hpp"

namespace dynamap::mapping {
namespace {

using Point = pcl::PointNormal;
using Cloud = pcl::PointCloud<Point>;
using Tree = FlannPointSearch<Point>;  // Not KdTreeFLANN: FlannPointSearch.hpp says why.

// Below this many points a cloud says too little to register against.
constexpr std::size_t kMinPoints = 10;

Cloud::Ptr ToCloud(const robotio::PointList& points) {
  auto cloud = std::make_shared<Cloud>();
  cloud->resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    Point& p = (*cloud)[i];
    p.x = points[i].x();
    p.y = points[i].y();
    p.z = points[i].z();
    p.normal_x = p.normal_y = p.normal_z = std::numeric_limits<float>::quiet_NaN();
    p.curvature = 0.0f;
  }
  cloud->width = static_cast<std::uint32_t>(points.size());
  cloud->height = 1;
  cloud->is_dense = true;
  return cloud;
}

// Exposes the iteration count, which PCL keeps protected.
class Icp : public pcl::IterativeClosestPoint<Point, Point, float> {
 public:
  [[nodiscard]] int Iterations() const { return nr_iterations_; }
};

bool StoppedByConvergence(Icp& icp) {
  using Criteria = pcl::registration::DefaultConvergenceCriteria<float>;
  const auto criteria = icp.getConvergeCriteria();
  if (!criteria) return icp.hasConverged();
  switch (criteria->getConvergenceState()) {
    case Criteria::CONVERGENCE_CRITERIA_TRANSFORM:
    case Criteria::CONVERGENCE_CRITERIA_ABS_MSE:
    case Criteria::CONVERGENCE_CRITERIA_REL_MSE:
      return icp.hasConverged();
    default:
      return false;
  }
}

}  // namespace

RegistrationConfig ParseRegistrationConfig(robotio::ConfigNode& node) {
  RegistrationConfig config;
  std::string metric =
      config.metric == IcpMetric::kPointToPlane ? "point_to_plane" : "point_to_point";
  node.ReadChoice("metric", &metric, {"point_to_point", "point_to_plane"});
  config.metric = metric == "point_to_plane" ? IcpMetric::kPointToPlane : IcpMetric::kPointToPoint;
  node.Read("planar", &config.planar);
  node.Read("max_iterations", &config.max_iterations, 1, 1000);
  node.Read("max_correspondence_distance_m", &config.max_correspondence_distance_m, 1e-4, 10.0);
  node.Read("transformation_epsilon", &config.transformation_epsilon, 0.0, 1.0);
  node.Read("euclidean_fitness_epsilon", &config.euclidean_fitness_epsilon, 0.0, 1.0);
  node.Read("trim_ratio", &config.trim_ratio, 0.05, 1.0);
  node.Read("normal_neighbours", &config.normal_neighbours, 3, 100);
  return config;
}

struct Registration::Impl {
  Cloud::Ptr target = std::make_shared<Cloud>();
  Tree::Ptr tree = std::make_shared<Tree>();
};

Registration::Registration(RegistrationConfig config)
    : config_(config), impl_(std::make_unique<Impl>()) {
  // A failed alignment is told by RegistrationResult; PCL would also print an error line
  // for every scan without enough correspondences (a robot turning towards unmapped
  // space), tens per second through the progress line.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
}
Registration::~Registration() = default;
Registration::Registration(Registration&&) noexcept = default;
Registration& Registration::operator=(Registration&&) noexcept = default;

std::size_t Registration::target_size() const { return impl_->target->size(); }

void Registration::SetTarget(const robotio::PointList& target) {
  impl_->target = ToCloud(target);
  impl_->tree = std::make_shared<Tree>();
  if (target.empty()) return;
  impl_->tree->setInputCloud(impl_->target);
  if (config_.metric == IcpMetric::kPointToPlane && target.size() >= kMinPoints) {
    pcl::NormalEstimation<Point, Point> estimation;
    estimation.setInputCloud(impl_->target);
    estimation.setSearchMethod(impl_->tree);
    estimation.setKSearch(config_.normal_neighbours);
    Cloud normals;
    estimation.compute(normals);
    for (std::size_t i = 0; i < normals.size(); ++i) {
      (*impl_->target)[i].normal_x = normals[i].normal_x;
      (*impl_->target)[i].normal_y = normals[i].normal_y;
      (*impl_->target)[i].normal_z = normals[i].normal_z;
      (*impl_->target)[i].curvature = normals[i].curvature;
    }
  }
}

RegistrationResult Registration::Align(const robotio::PointList& source,
                                       const Eigen::Isometry3d& guess_T_target_source) const {
  RegistrationResult result;
  result.T_target_source = guess_T_target_source;
  if (source.size() < kMinPoints || impl_->target->size() < kMinPoints) return result;

  Icp icp;
  icp.setInputSource(ToCloud(source));
  icp.setInputTarget(impl_->target);
  // The tree was built for this target in SetTarget; ICP must not rebuild it per call.
  icp.setSearchMethodTarget(impl_->tree, /*force_no_recompute=*/true);
  icp.setMaximumIterations(config_.max_iterations);
  icp.setMaxCorrespondenceDistance(config_.max_correspondence_distance_m);
  icp.setTransformationEpsilon(config_.transformation_epsilon);
  // PCL disables the relative-MSE test with -max; 0 means "disabled" here.
  icp.setEuclideanFitnessEpsilon(config_.euclidean_fitness_epsilon > 0.0
                                     ? config_.euclidean_fitness_epsilon
                                     : -std::numeric_limits<double>::max());
  if (config_.trim_ratio < 1.0) {
    auto trimmed = std::make_shared<pcl::registration::CorrespondenceRejectorTrimmed>();
    trimmed->setOverlapRatio(static_cast<float>(config_.trim_ratio));
    trimmed->setMinCorrespondences(static_cast<unsigned int>(kMinPoints));
    icp.addCorrespondenceRejector(trimmed);
  }
  const bool point_to_plane = config_.metric == IcpMetric::kPointToPlane;
  if (config_.planar) {
    icp.setTransformationEstimation(
        std::make_shared<internal::PlanarTransformationEstimation>(point_to_plane));
  } else if (point_to_plane) {
    icp.setTransformationEstimation(
        std::make_shared<
            pcl::registration::TransformationEstimationPointToPlaneLLS<Point, Point, float>>());
  }

  Cloud aligned;
  icp.align(aligned, guess_T_target_source.matrix().cast<float>());
  result.iterations = icp.Iterations();
  result.converged = StoppedByConvergence(icp);
  result.T_target_source.matrix() = icp.getFinalTransformation().cast<double>();

  // Fit quality over the final alignment: one nearest-neighbour query per source point.
  const double max_sq = config_.max_correspondence_distance_m * config_.max_correspondence_distance_m;
  std::size_t inliers = 0;
  const Eigen::Vector3d origin = result.T_target_source.translation();
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
  double sum_sq = 0.0;
  pcl::Indices index(1);
  std::vector<float> sq_distance(1);
  for (const Point& p : aligned) {
    if (impl_->tree->nearestKSearch(p, 1, index, sq_distance) < 1) continue;
    if (sq_distance[0] > max_sq) continue;
    ++inliers;
    sum_sq += sq_distance[0];
    const Point& q = (*impl_->target)[static_cast<std::size_t>(index[0])];
    if (std::isfinite(q.normal_x)) {
      const double px = p.x - origin.x();
      const double py = p.y - origin.y();
      const Eigen::Vector3d J(q.normal_x, q.normal_y, px * q.normal_y - py * q.normal_x);
      information += J * J.transpose();
    }
  }
  if (inliers > 0) result.planar_information = information / static_cast<double>(inliers);
  result.inlier_ratio = static_cast<double>(inliers) / static_cast<double>(aligned.size());
  if (inliers > 0) result.fitness_rmse_m = std::sqrt(sum_sq / static_cast<double>(inliers));
  return result;
}

RegistrationResult RegisterScans(const robotio::PointList& source,
                                 const robotio::PointList& target,
                                 const Eigen::Isometry3d& guess_T_target_source,
                                 const RegistrationConfig& config) {
  Registration registration(config);
  registration.SetTarget(target);
  return registration.Align(source, guess_T_target_source);
}

double PlanarStructure(const Eigen::Matrix3d& planar_information) {
  const Eigen::Vector3d values =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(planar_information).eigenvalues();
  return values(2) > 0.0 ? values(0) / values(2) : 0.0;
}

}  // namespace dynamap::mapping
