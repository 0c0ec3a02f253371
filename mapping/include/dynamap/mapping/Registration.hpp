// Scan registration with ICP (thesis ch. 3, Algorithm 1): point-to-point (Besl & McKay
// 1992) or point-to-plane (Chen & Medioni 1991), trimmed (Chetverikov et al. 2002), with
// a planar x/y/yaw mode for the planar base. PCL does the work behind this PCL-free header.
#pragma once

#include <Eigen/Geometry>
#include <limits>
#include <memory>

#include "dynamap/robotio/ConfigReader.hpp"
#include "dynamap/robotio/DepthProjection.hpp"

namespace dynamap::mapping {

enum class IcpMetric { kPointToPoint, kPointToPlane };

struct RegistrationConfig {
  IcpMetric metric = IcpMetric::kPointToPlane;  // Error the estimate minimises.
  // Estimate only x, y and yaw (z, roll, pitch stay as in the initial guess), since the
  // base moves in a plane; full 6-DoF otherwise.
  bool planar = true;
  int max_iterations = 30;                    // Hitting this counts as not converged.
  double max_correspondence_distance_m = 0.2; // m, pairs further apart are rejected.
  double transformation_epsilon = 1e-6;       // Squared change of the transform to stop at.
  double euclidean_fitness_epsilon = 1e-7;    // m², change in mean squared error to stop at.
  // Trimmed ICP: share of the closest correspondences kept each iteration, in (0, 1];
  // 1 keeps every pair within the distance limit.
  double trim_ratio = 0.9;
  int normal_neighbours = 12;  // Target points per normal fit (point-to-plane only).
};

// Reads the keys of a "registration:" mapping; unknown keys are errors.
[[nodiscard]] RegistrationConfig ParseRegistrationConfig(robotio::ConfigNode& node);

struct RegistrationResult {
  // The estimate stopped because it stopped changing (not at the iteration limit and not
  // for lack of correspondences).
  bool converged = false;
  Eigen::Isometry3d T_target_source = Eigen::Isometry3d::Identity();
  // m, RMS distance of the source points to their nearest target point after alignment,
  // over the points within max_correspondence_distance_m.
  double fitness_rmse_m = std::numeric_limits<double>::infinity();
  double inlier_ratio = 0.0;  // Share of source points within the distance limit, [0, 1].
  int iterations = 0;
  // Planar point-to-plane information at the final pose, mean of J Jᵀ over the inlier
  // pairs with J = [nx, ny, (p − o) × n |z] (o: the source origin in the target frame),
  // order (x, y, yaw); zero when the target has no normals. A small eigenvalue marks a
  // direction the scene does not constrain, e.g. along a bare corridor.
  Eigen::Matrix3d planar_information = Eigen::Matrix3d::Zero();
};

// Holds the reference cloud with its search tree (and normals), so that several scans
// can be registered against one reference without rebuilding it.
class Registration {
 public:
  explicit Registration(RegistrationConfig config);
  ~Registration();
  Registration(Registration&&) noexcept;
  Registration& operator=(Registration&&) noexcept;
  Registration(const Registration&) = delete;
  Registration& operator=(const Registration&) = delete;

  [[nodiscard]] const RegistrationConfig& config() const { return config_; }
  // Points in the reference frame ("target"); builds the search tree and, for
  // point-to-plane, the normals.
  void SetTarget(const robotio::PointList& target);
  [[nodiscard]] std::size_t target_size() const;
  // Aligns `source` (points in the source frame) to the target, starting from the guess.
  // A result with converged == false when the target or source is too small.
  [[nodiscard]] RegistrationResult Align(const robotio::PointList& source,
                                         const Eigen::Isometry3d& guess_T_target_source) const;

 private:
  struct Impl;
  RegistrationConfig config_;
  std::unique_ptr<Impl> impl_;
};

// Smallest / largest eigenvalue of a planar information matrix: how well a registration
// pinned x, y and yaw (near 0 along a bare corridor); 0 without information.
[[nodiscard]] double PlanarStructure(const Eigen::Matrix3d& planar_information);

// One-shot convenience: SetTarget + Align.
[[nodiscard]] RegistrationResult RegisterScans(const robotio::PointList& source,
                                               const robotio::PointList& target,
                                               const Eigen::Isometry3d& guess_T_target_source,
                                               const RegistrationConfig& config);

}  // namespace dynamap::mapping
