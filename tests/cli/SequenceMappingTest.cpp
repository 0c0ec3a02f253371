// `dynamap map --log` on recordings without odometry: a TUM RGB-D sequence folder made of
// views of a real Kinect frame (with its motion-capture style ground truth) and an
// OpenNI2 .oni file.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "../robotio/TestPaths.hpp"
#include "../support/CommandRunner.hpp"
#include "../support/DummyOni.hpp"
#include "../support/ReprojectedView.hpp"
#include "dynamap/robotio/DepthImageIo.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap {
namespace {

namespace fs = std::filesystem;
constexpr double kPi = 3.14159265358979323846;

using test::CommandResult;
using test::ReadJson;
using test::RunDynamap;

std::size_t CountLines(const std::string& file) {
  std::ifstream in(file);
  std::size_t lines = 0;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line[0] != '#') ++lines;
  }
  return lines;
}

// A hand-held camera's path: 1.5 cm and 0.4° of yaw per frame, a little pitch and height.
Eigen::Isometry3d BodyPose(int k) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = (Eigen::AngleAxisd(0.4 * kPi / 180.0 * k, Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(0.5 * kPi / 180.0 * std::sin(0.3 * k), Eigen::Vector3d::UnitY()))
                      .toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.015 * k, 0.004 * k, 0.01 * std::sin(0.2 * k));
  return pose;
}

// Writes a TUM RGB-D sequence folder: depth.txt and depth/*.png (value = m * 5000), and
// groundtruth.txt with the optical frame's pose in a motion-capture frame of its own.
void WriteTumSequence(const std::string& dir, int frames) {
  auto image = robotio::ReadDepthImage(test::SharedData("tum/TUM_depth.png"));
  ASSERT_TRUE(image.ok()) << image.error().message;
  robotio::DepthFrame real;
  real.width = image->width;
  real.height = image->height;
  real.depth_mm = robotio::TumToMillimetres(image->values);
  const Eigen::Isometry3d mount =
      robotio::MountPose(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  Eigen::Isometry3d mocap_from_start = Eigen::Isometry3d::Identity();
  mocap_from_start.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.2, -0.3, 1.0).normalized())
                                  .toRotationMatrix();
  mocap_from_start.translation() = Eigen::Vector3d(1.3, -0.6, 1.5);
  fs::create_directories(dir + "/depth");
  std::ofstream index(dir + "/depth.txt");
  std::ofstream truth(dir + "/groundtruth.txt");
  index << "# depth maps\n# timestamp filename\n";
  truth << "# ground truth trajectory\n# timestamp tx ty tz qx qy qz qw\n";
  const double t0 = 1305031102.0;
  for (int k = 0; k < frames; ++k) {
    const Eigen::Isometry3d T_old_new = mount.inverse() * BodyPose(k) * mount;
    const robotio::DepthFrame view = test::ReprojectedView(real, T_old_new);
    char stamp[32];
    std::snprintf(stamp, sizeof stamp, "%.6f", t0 + k / 30.0);
    robotio::DepthImage png{view.width, view.height, robotio::MillimetresToTum(view.depth_mm)};
    ASSERT_TRUE(robotio::WriteDepthPng(png, dir + "/depth/" + stamp + ".png").ok());
    index << stamp << " depth/" << stamp << ".png\n";
    const Eigen::Isometry3d optical = mocap_from_start * T_old_new;
    const Eigen::Quaterniond q(optical.rotation());
    const Eigen::Vector3d p = optical.translation();
    truth << stamp << ' ' << p.x() << ' ' << p.y() << ' ' << p.z() << ' ' << q.x() << ' '
          << q.y() << ' ' << q.z() << ' ' << q.w() << '\n';
  }
}

TEST(SequenceMapping, TumSequenceIsTrackedByRegistrationAlone) {
  const std::string dir = test::ScratchDir();
  constexpr int kFrames = 20;
  WriteTumSequence(dir + "/sequence", kFrames);
  if (HasFatalFailure()) return;
  const std::string out = dir + "/out";
  const CommandResult run =
      RunDynamap("map --log " + dir + "/sequence --out " + out, dir + "/map.log");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json report = ReadJson(out + "/report.json");
  EXPECT_EQ(report["pose_source"], "registration only (no odometry)");
  EXPECT_EQ(report["reference"], "keyframes");
  EXPECT_FALSE(report.contains("slam_odometry"));
  EXPECT_EQ(report["frames_processed"], kFrames);
  EXPECT_GE(report["registrations_accepted"].get<int>(), kFrames - 2);
  EXPECT_TRUE(report["ate_aligned"].get<bool>());
  ASSERT_TRUE(report["ate_rmse_m"].is_number()) << report.dump(2);
  EXPECT_LT(report["ate_rmse_m"].get<double>(), 0.01);
  EXPECT_TRUE(report["odometry_ate_rmse_m"].is_null());
  EXPECT_EQ(report["track_restarts"], 0);
  EXPECT_GT(report["static_occupied_voxels"].get<int>(), 1000);
  EXPECT_EQ(CountLines(out + "/trajectory.tum"), static_cast<std::size_t>(kFrames));
  for (const char* file : {"map.ot", "static.bt", "static.ply", "topdown.png"}) {
    EXPECT_TRUE(fs::exists(out + "/" + file)) << file;
  }
}

TEST(SequenceMapping, OdometryPosesOfASequenceWithoutOdometryAreAClearError) {
  const std::string dir = test::ScratchDir();
  WriteTumSequence(dir + "/sequence", 2);
  if (HasFatalFailure()) return;
  const CommandResult run = RunDynamap(
      "map --poses odometry --log " + dir + "/sequence --out " + dir + "/out", dir + "/map.log");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("sequence: no odometry.txt"), std::string::npos) << run.output;
}

// Debian's OpenNI2 (2.2.0.33) opens a file recorded from its software device and counts
// its frames, but its file device plays none back: the command must say so, not hang.
TEST(SequenceMapping, OniFileThatPlaysNothingIsAClearError) {
  const std::string dir = test::ScratchDir();
  const std::string oni = dir + "/dummy.oni";
  int recorded = 0;
  ASSERT_NO_FATAL_FAILURE(test::RecordDummyOni(oni, 4, &recorded));
  ASSERT_EQ(recorded, 4);
  const CommandResult run = RunDynamap("map --log " + oni + " --out " + dir + "/out", dir + "/map.log");
  if (run.exit_code == 0) {
    // An OpenNI2 that does play files back: then the frames must have been mapped.
    const nlohmann::json report = ReadJson(dir + "/out/report.json");
    EXPECT_GT(report["frames_processed"].get<int>(), 0);
    return;
  }
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("OpenNI2 recording " + oni), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("played nothing back"), std::string::npos) << run.output;
}

TEST(SequenceMapping, MissingOniFileNamesIt) {
  const std::string dir = test::ScratchDir();
  const CommandResult run =
      RunDynamap("map --log " + dir + "/absent.oni --out " + dir + "/out", dir + "/map.log");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(dir + "/absent.oni: no such file"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace dynamap
