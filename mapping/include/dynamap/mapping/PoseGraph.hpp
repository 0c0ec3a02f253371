// Planar pose graph: poses (x, y, yaw) linked by measured relative poses, each with its
// information matrix, solved as nonlinear least squares (Ceres behind this header).
#pragma once

#include <cstddef>
#include <vector>

#include <Eigen/Core>

#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::mapping {

// `to` measured in `from`'s frame (from⁻¹ ⊕ to), order of information: x, y, yaw.
struct PoseGraphEdge {
  std::size_t from = 0;
  std::size_t to = 0;
  robotio::Pose2D measured;
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
  // A loop closure, which may be wrong: dropped when, after a solve, it disagrees with
  // the rest of the graph by more than the gate (a robust loss instead would also damp a
  // right closure after long drift, which starts out many sigmas off).
  bool closure = false;
};

struct PoseGraphSummary {
  bool converged = false;
  int iterations = 0;                 // Of the last solve.
  // Closures that disagreed with the rest, by their index in the edge list.
  std::vector<std::size_t> dropped;
  double initial_cost = 0.0;  // ½ Σ of squared whitened residuals (after the loss).
  double final_cost = 0.0;
};

// Moves `poses` to the least-squares fit of the edges; the first pose stays fixed (it
// anchors the map frame). After each solve the closure with the largest squared
// whitened error above `closure_gate` (χ² with 3 degrees of freedom; 16.27 is its 99.9 %
// quantile) is dropped and the graph solved again from the starting poses, until every
// closure left agrees. Edges naming a pose that does not exist are ignored.
PoseGraphSummary OptimizePoseGraph(std::vector<robotio::Pose2D>* poses,
                                   const std::vector<PoseGraphEdge>& edges,
                                   double closure_gate = 16.27);

}  // namespace dynamap::mapping
