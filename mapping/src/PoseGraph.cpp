#include "dynamap/mapping/PoseGraph.hpp"

#include <ceres/ceres.h>

#include <Eigen/Eigenvalues>
#include <array>
#include <cmath>

namespace dynamap::mapping {
namespace {

template <typename T>
T NormalizedAngle(const T& angle) {
  const T two_pi(2.0 * M_PI);
  return angle - two_pi * ceres::floor((angle + T(M_PI)) / two_pi);
}

// Residual of one edge: the measured pose of `to` in `from`'s frame against the one the
// current estimates give, whitened by the square root of the information.
class RelativePoseError {
 public:
  RelativePoseError(const robotio::Pose2D& measured, const Eigen::Matrix3d& sqrt_information)
      : measured_(measured), sqrt_information_(sqrt_information) {}

  template <typename T>
  bool operator()(const T* from, const T* to, T* residual) const {
    const T c = ceres::cos(from[2]);
    const T s = ceres::sin(from[2]);
    const T dx = to[0] - from[0];
    const T dy = to[1] - from[1];
    Eigen::Matrix<T, 3, 1> error;
    error(0) = c * dx + s * dy - T(measured_.x);
    error(1) = -s * dx + c * dy - T(measured_.y);
    error(2) = NormalizedAngle(to[2] - from[2] - T(measured_.theta));
    Eigen::Map<Eigen::Matrix<T, 3, 1>>{residual} = sqrt_information_.cast<T>() * error;
    return true;
  }

 private:
  robotio::Pose2D measured_;
  Eigen::Matrix3d sqrt_information_;
};

// U with UᵀU = information, so |U e|² = eᵀ information e; a direction without
// information (a corridor's axis) gets a zero row instead of failing a factorisation.
Eigen::Matrix3d SquareRoot(const Eigen::Matrix3d& information) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(information);
  const Eigen::Vector3d roots = eigen.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  return roots.asDiagonal() * eigen.eigenvectors().transpose();
}

using State = std::vector<std::array<double, 3>>;

// One least-squares solve over the edges marked in `use`; false when nothing constrains
// the graph.
bool Solve(const std::vector<PoseGraphEdge>& edges, const std::vector<bool>& use, State* state,
           PoseGraphSummary* summary) {
  ceres::Problem problem;
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (!use[e]) continue;
    const PoseGraphEdge& edge = edges[e];
    problem.AddResidualBlock(new ceres::AutoDiffCostFunction<RelativePoseError, 3, 3, 3>(
                                 new RelativePoseError(edge.measured, SquareRoot(edge.information))),
                             nullptr, (*state)[edge.from].data(), (*state)[edge.to].data());
  }
  if (!problem.HasParameterBlock((*state)[0].data())) return false;
  problem.SetParameterBlockConstant((*state)[0].data());
  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 100;
  options.num_threads = 1;
  ceres::Solver::Summary result;
  ceres::Solve(options, &problem, &result);
  summary->converged = result.termination_type == ceres::CONVERGENCE;
  summary->iterations = static_cast<int>(result.iterations.size());
  summary->initial_cost = result.initial_cost;
  summary->final_cost = result.final_cost;
  return true;
}

double SquaredError(const PoseGraphEdge& edge, const State& state) {
  const RelativePoseError error(edge.measured, SquareRoot(edge.information));
  Eigen::Vector3d residual;
  error(state[edge.from].data(), state[edge.to].data(), residual.data());
  return residual.squaredNorm();
}

}  // namespace

PoseGraphSummary OptimizePoseGraph(std::vector<robotio::Pose2D>* poses,
                                   const std::vector<PoseGraphEdge>& edges,
                                   double closure_gate) {
  PoseGraphSummary summary;
  summary.converged = true;
  State start(poses->size());
  for (std::size_t i = 0; i < poses->size(); ++i) {
    start[i] = {(*poses)[i].x, (*poses)[i].y, (*poses)[i].theta};
  }
  std::vector<bool> use(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    use[e] = edges[e].from < start.size() && edges[e].to < start.size() &&
             edges[e].from != edges[e].to;
  }
  State state = start;
  while (true) {
    state = start;
    if (!Solve(edges, use, &state, &summary)) return summary;
    std::size_t worst = edges.size();
    double worst_error = closure_gate;
    for (std::size_t e = 0; e < edges.size(); ++e) {
      if (!use[e] || !edges[e].closure) continue;
      const double error = SquaredError(edges[e], state);
      if (error > worst_error) {
        worst_error = error;
        worst = e;
      }
    }
    if (worst == edges.size()) break;
    use[worst] = false;
    summary.dropped.push_back(worst);
  }
  for (std::size_t i = 0; i < poses->size(); ++i) {
    (*poses)[i] = {state[i][0], state[i][1], robotio::WrapAngle(state[i][2])};
  }
  return summary;
}

}  // namespace dynamap::mapping
