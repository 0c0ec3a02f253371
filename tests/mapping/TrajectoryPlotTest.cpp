#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "dynamap/mapping/TrajectoryPlot.hpp"

namespace dynamap::mapping {
namespace {

robotio::Trajectory Line(double offset_y, double stamp_offset_s = 0.0) {
  robotio::Trajectory trajectory;
  for (int k = 0; k <= 100; ++k) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.translation() = Eigen::Vector3d(0.05 * k, offset_y * k / 100.0, 0.0);
    trajectory.push_back(
        {static_cast<std::int64_t>((0.1 * k + stamp_offset_s) * 1e9) + 1'000'000'000, pose});
  }
  return trajectory;
}

TEST(TrajectoryPlot, ErrorsAreTheDistancesOfAssociatedPosesOverTime) {
  const robotio::Trajectory truth = Line(0.0);
  // Stamps 5 ms late associate; an error growing linearly to 0.2 m at 10 s.
  const auto errors = PositionErrorOverTime(truth, Line(0.2, 0.005));
  ASSERT_EQ(errors.size(), 101u);
  EXPECT_NEAR(errors.front().first, 0.0, 1e-9);
  EXPECT_NEAR(errors.back().first, 10.0, 1e-9);
  EXPECT_NEAR(errors[50].second, 0.1, 1e-9);
  EXPECT_NEAR(errors.back().second, 0.2, 1e-9);
  // 50 ms apart: nothing associates.
  EXPECT_TRUE(PositionErrorOverTime(truth, Line(0.2, 0.05)).empty());
}

TEST(TrajectoryPlot, DrawsOneLineInItsOwnColourPerEstimate) {
  const std::string file =
      (std::filesystem::temp_directory_path() / "dynamap_trajectory_error.png").string();
  std::remove(file.c_str());
  const robotio::Trajectory truth = Line(0.0);
  ASSERT_TRUE(WriteTrajectoryErrorPlot(file, truth,
                                       {{"SLAM", Line(0.05)}, {"odometry alone", Line(0.4)}})
                  .ok());
  const cv::Mat image = cv::imread(file, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 1000);
  EXPECT_EQ(image.rows, 420);
  // The first line is blue (BGR 200, 90, 30), the second orange (40, 140, 230).
  int blue = 0, orange = 0;
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      const cv::Vec3b p = image.at<cv::Vec3b>(r, c);
      blue += p == cv::Vec3b(200, 90, 30) ? 1 : 0;
      orange += p == cv::Vec3b(40, 140, 230) ? 1 : 0;
    }
  }
  EXPECT_GT(blue, 500);
  EXPECT_GT(orange, 500);

  const auto nothing = WriteTrajectoryErrorPlot(file, truth, {{"SLAM", {}}});
  ASSERT_FALSE(nothing.ok());
  EXPECT_NE(nothing.error().message.find(file), std::string::npos);
  std::remove(file.c_str());
}

}  // namespace
}  // namespace dynamap::mapping
