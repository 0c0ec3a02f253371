#include "dynamap/mapping/TrajectoryEvaluation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace dynamap::mapping {
namespace {

using robotio::StampedPose;
using robotio::Trajectory;

std::string TumData(const std::string& name) {
  return std::string(DYNAMAP_SHARED_DATA_DIR) + "/tum/" + name;
}

Trajectory Line(int n, std::int64_t offset_ns, double y_offset) {
  Trajectory trajectory;
  for (int i = 0; i < n; ++i) {
    StampedPose pose;
    pose.stamp_ns = i * 100'000'000LL + offset_ns;
    pose.pose.translation() = Eigen::Vector3d(0.1 * i, y_offset, 0.0);
    trajectory.push_back(pose);
  }
  return trajectory;
}

TEST(TrajectoryEvaluation, TumDeskOrbMatchesBenchmarkScript) {
  const auto gt = robotio::ReadTumTrajectory(TumData("fr2_desk_groundtruth.txt"));
  const auto est = robotio::ReadTumTrajectory(TumData("fr2_desk_ORB.txt"));
  ASSERT_TRUE(gt.ok()) << gt.error().message;
  ASSERT_TRUE(est.ok()) << est.error().message;
  TrajectoryEvaluationConfig config;
  config.align = true;
  const auto result = EvaluateTrajectory(*gt, *est, config);
  ASSERT_TRUE(result.has_value());
  EXPECT_EQ(result->pairs, 2223u);
  EXPECT_NEAR(result->ate_m.rmse, 0.008144, 1e-4);
  EXPECT_NEAR(result->ate_m.mean, 0.007514, 1e-4);
  EXPECT_NEAR(result->ate_m.median, 0.007432, 1e-4);
  EXPECT_NEAR(result->ate_m.max, 0.024329, 1e-4);
}

TEST(TrajectoryEvaluation, AssociationRespectsLimitAndUsesEachStampOnce) {
  const Trajectory gt = Line(5, 0, 0.0);
  Trajectory est = Line(5, 15'000'000, 0.0);  // 15 ms late: all within 20 ms.
  EXPECT_EQ(AssociateStamps(gt, est, 0.02).size(), 5u);
  est = Line(5, 25'000'000, 0.0);  // 25 ms late: none.
  EXPECT_TRUE(AssociateStamps(gt, est, 0.02).empty());
  // Two estimates near one ground-truth stamp: the closer one wins, the other stays free.
  Trajectory one = Line(1, 0, 0.0);
  Trajectory two = Line(1, 10'000'000, 0.0);
  two.push_back(two.front());
  two.back().stamp_ns = 3'000'000;
  const auto matches = AssociateStamps(one, two, 0.02);
  ASSERT_EQ(matches.size(), 1u);
  EXPECT_EQ(matches.front().second, 1u);
}

TEST(TrajectoryEvaluation, AlignmentRemovesRigidOffsetButNotScale) {
  const Trajectory gt = Line(20, 0, 0.0);
  Trajectory est = gt;
  const Eigen::Isometry3d T(Eigen::Translation3d(1, 2, 3) *
                            Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ()));
  for (auto& p : est) p.pose = T * p.pose;
  TrajectoryEvaluationConfig config;
  EXPECT_GT(EvaluateTrajectory(gt, est, config)->ate_m.rmse, 1.0);
  config.align = true;
  EXPECT_NEAR(EvaluateTrajectory(gt, est, config)->ate_m.rmse, 0.0, 1e-9);
  for (auto& p : est) p.pose.translation() *= 2.0;
  EXPECT_GT(EvaluateTrajectory(gt, est, config)->ate_m.rmse, 0.1);
}

TEST(TrajectoryEvaluation, ConstantOffsetGivesAteWithoutAlignment) {
  const auto result = EvaluateTrajectory(Line(30, 0, 0.0), Line(30, 0, 0.05), {});
  ASSERT_TRUE(result.has_value());
  EXPECT_NEAR(result->ate_m.rmse, 0.05, 1e-12);
  EXPECT_NEAR(result->ate_m.std, 0.0, 1e-9);
  // The offset is the same everywhere: no relative error.
  ASSERT_TRUE(result->rpe.has_value());
  EXPECT_NEAR(result->rpe->trans_m_per_m, 0.0, 1e-12);
}

TEST(TrajectoryEvaluation, RpeIsPerMetreTravelled) {
  // Estimate stretched by 10 %: 0.1 m error per metre, no rotation error.
  const Trajectory gt = Line(41, 0, 0.0);
  Trajectory est = gt;
  for (auto& p : est) p.pose.translation() *= 1.1;
  const auto result = EvaluateTrajectory(gt, est, {});
  ASSERT_TRUE(result->rpe.has_value());
  EXPECT_NEAR(result->rpe->trans_m_per_m, 0.1, 1e-9);
  EXPECT_NEAR(result->rpe->rot_deg_per_m, 0.0, 1e-9);
  // Shorter than one segment: no RPE.
  EXPECT_FALSE(EvaluateTrajectory(Line(5, 0, 0.0), Line(5, 0, 0.0), {})->rpe.has_value());
}

}  // namespace
}  // namespace dynamap::mapping
