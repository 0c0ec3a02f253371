#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynamap/mapping/PoseGraph.hpp"

namespace dynamap::mapping {
namespace {

using robotio::Pose2D;

// A 4 m square driven in 0.5 m steps with a quarter turn at each corner, back to the start.
std::vector<Pose2D> SquareLoop() {
  std::vector<Pose2D> poses{{0.0, 0.0, 0.0}};
  for (int side = 0; side < 4; ++side) {
    for (int step = 0; step < 8; ++step) poses.push_back(poses.back().Compose({0.5, 0.0, 0.0}));
    poses.back() = poses.back().Compose({0.0, 0.0, M_PI / 2.0});
  }
  return poses;
}

Eigen::Matrix3d Information(double sigma_m, double sigma_rad) {
  return Eigen::Vector3d(1.0 / (sigma_m * sigma_m), 1.0 / (sigma_m * sigma_m),
                         1.0 / (sigma_rad * sigma_rad))
      .asDiagonal();
}

double Distance(const Pose2D& a, const Pose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Odometry whose every step turns 0.01 rad too far: the chain alone ends far from the start.
std::vector<PoseGraphEdge> BiasedSequence(const std::vector<Pose2D>& truth,
                                          std::vector<Pose2D>* dead_reckoned) {
  std::vector<PoseGraphEdge> edges;
  dead_reckoned->assign(1, truth.front());
  for (std::size_t k = 1; k < truth.size(); ++k) {
    Pose2D step = truth[k - 1].Between(truth[k]);
    step.theta += 0.01;
    edges.push_back({k - 1, k, step, Information(0.01, 0.005), false});
    dead_reckoned->push_back(dead_reckoned->back().Compose(step));
  }
  return edges;
}

TEST(PoseGraph, ALoopClosureTakesOutTheDriftOfABiasedChain) {
  const std::vector<Pose2D> truth = SquareLoop();
  std::vector<Pose2D> poses;
  std::vector<PoseGraphEdge> edges = BiasedSequence(truth, &poses);
  const double drift_before = Distance(poses.back(), truth.back());
  ASSERT_GT(drift_before, 0.5);
  // The last pose seen again from the first, and a quarter of the way round.
  edges.push_back({0, truth.size() - 1, truth.front().Between(truth.back()),
                   Information(0.005, 0.002), true});
  edges.push_back({8, 24, truth[8].Between(truth[24]), Information(0.005, 0.002), true});
  const PoseGraphSummary summary = OptimizePoseGraph(&poses, edges);
  EXPECT_TRUE(summary.converged);
  EXPECT_LT(summary.final_cost, summary.initial_cost);
  double worst = 0.0;
  for (std::size_t k = 0; k < truth.size(); ++k) worst = std::max(worst, Distance(poses[k], truth[k]));
  EXPECT_LT(worst, 0.1 * drift_before) << "before " << drift_before;
  EXPECT_LT(Distance(poses.back(), truth.back()), 0.02);
  // The first pose anchors the frame.
  EXPECT_EQ(poses.front().x, 0.0);
  EXPECT_EQ(poses.front().y, 0.0);
  EXPECT_EQ(poses.front().theta, 0.0);
}

TEST(PoseGraph, AClosureThatDisagreesWithTheRestIsDropped) {
  const std::vector<Pose2D> truth = SquareLoop();
  std::vector<Pose2D> poses;
  std::vector<PoseGraphEdge> edges = BiasedSequence(truth, &poses);
  for (std::size_t k = 28; k < truth.size(); ++k) {
    edges.push_back({k - 28, k, truth[k - 28].Between(truth[k]), Information(0.005, 0.002), true});
  }
  // One closure that says pose 20 sits 1.5 m from where it is.
  Pose2D wrong = truth[4].Between(truth[20]);
  wrong.x += 1.5;
  edges.push_back({4, 20, wrong, Information(0.005, 0.002), true});
  const PoseGraphSummary summary = OptimizePoseGraph(&poses, edges);
  ASSERT_EQ(summary.dropped.size(), 1u);
  EXPECT_EQ(summary.dropped.front(), edges.size() - 1);  // The wrong closure, no other.
  EXPECT_LT(Distance(poses[20], truth[20]), 0.1);
  EXPECT_LT(Distance(poses.back(), truth.back()), 0.03);
}

TEST(PoseGraph, AClosureWithoutInformationAlongACorridorLeavesThatDirectionToTheChain) {
  // Three poses in a row along x; the closure from 0 to 2 knows y and yaw only (a
  // corridor along x) and says pose 2 lies 0.3 m further along x and 0.1 m to the side.
  std::vector<Pose2D> poses{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {2.0, 0.0, 0.0}};
  std::vector<PoseGraphEdge> edges{{0, 1, {1.0, 0.0, 0.0}, Information(0.01, 0.005), false},
                                   {1, 2, {1.0, 0.0, 0.0}, Information(0.01, 0.005), false}};
  PoseGraphEdge closure{0, 2, {2.3, 0.1, 0.0}, Eigen::Matrix3d::Zero(), false};
  closure.information(1, 1) = 1.0 / (0.002 * 0.002);
  closure.information(2, 2) = 1.0 / (0.001 * 0.001);
  edges.push_back(closure);
  OptimizePoseGraph(&poses, edges);
  EXPECT_NEAR(poses[2].x, 2.0, 0.01);  // Along the corridor: the chain's 2 m.
  EXPECT_NEAR(poses[2].y, 0.1, 0.02);  // Across it: the closure.
}

}  // namespace
}  // namespace dynamap::mapping
