#include "dynamap/calibration/CalibrationSession.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "SyntheticCapture.hpp"

namespace dynamap::calibration {
namespace {

constexpr std::int64_t kMs = 1000000;

// What a Kinect mounted as `mount` sees of an endless flat floor (low resolution).
robotio::DepthFrame FloorFrame(const robotio::KinectMount& mount, int sensor,
                               std::int64_t stamp_ns) {
  robotio::DepthFrame frame;
  frame.sensor_id = sensor;
  frame.stamp_ns = stamp_ns;
  frame.received_ns = stamp_ns;
  frame.width = 160;
  frame.height = 120;
  frame.intrinsics = robotio::Intrinsics{}.Scaled(160, 120);
  frame.depth_mm.assign(160 * 120, 0);
  const Eigen::Matrix3d R = mount.T_base_kinect.linear();
  const double height = mount.T_base_kinect.translation().z();
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      const Eigen::Vector3d ray((u - frame.intrinsics.cx) / frame.intrinsics.fx,
                                (v - frame.intrinsics.cy) / frame.intrinsics.fy, 1.0);
      const double down = (R * ray).z();
      if (down >= -1e-3) continue;
      const double z = height / -down;  // Depth along optical z (ray has z = 1).
      if (z < 4.0) frame.depth_mm[v * 160 + u] = static_cast<std::uint16_t>(std::lround(z * 1000));
    }
  }
  return frame;
}

// Feeds `seconds` of odometry (50 Hz) and gyro (100 Hz) for constant (v, omega).
void Drive(CalibrationSession* session, std::int64_t* t_ns, double v, double omega,
           double seconds, double* left, double* right) {
  const double track = 0.54;
  for (int i = 0; i < static_cast<int>(seconds * 100); ++i) {
    *t_ns += 10 * kMs;
    session->AddImu({*t_ns, 0.0, 0.0, omega + 0.003});
    if (i % 2 == 1) {
      *left += (v - 0.5 * track * omega) * 0.02;
      *right += (v + 0.5 * track * omega) * 0.02;
      session->AddOdometry({*t_ns, *left, *right});
    }
  }
}

TEST(CalibrationSession, WalksTheStepsAndRefusesToSaveWhatIsNotCalibrated) {
  const robotio::Rig rig = test::TrueRig();
  SessionConfig config;
  config.floor_frames = 5;
  CalibrationSession session(rig, config);
  std::int64_t t = 0;
  double left = 0.0, right = 0.0;
  EXPECT_EQ(session.step(), SessionStep::kFloor);
  EXPECT_FALSE(session.Advance().ok());  // No floor yet.

  for (int i = 0; i < 5; ++i) {
    Drive(&session, &t, 0.0, 0.0, 0.2, &left, &right);
    for (int k = 0; k < 2; ++k) session.AddDepth(FloorFrame(rig.kinects[k], k, t));
  }
  SessionProgress p = session.Progress();
  EXPECT_EQ(p.floor_fits, (std::vector<int>{5, 5}));
  EXPECT_TRUE(p.complete);
  EXPECT_NEAR(session.gyro_bias_rad_s(), 0.003, 1e-9);  // Learned while standing still.
  ASSERT_TRUE(session.Advance().ok());
  EXPECT_EQ(session.step(), SessionStep::kTurn);

  // Turning is counted each way (gyro bias removed); without frames there are no pairs.
  Drive(&session, &t, 0.0, 0.8, 6.0, &left, &right);
  Drive(&session, &t, 0.0, -0.8, 3.0, &left, &right);
  p = session.Progress();
  EXPECT_NEAR(p.turned_left_deg, 0.8 * 6.0 * 180.0 / M_PI, 3.0);
  EXPECT_NEAR(p.turned_right_deg, 0.8 * 3.0 * 180.0 / M_PI, 3.0);
  EXPECT_FALSE(p.complete);
  const robotio::Status refused = session.Advance();
  ASSERT_FALSE(refused.ok());
  EXPECT_NE(refused.error().message.find("incomplete"), std::string::npos);

  session.Skip();
  EXPECT_EQ(session.step(), SessionStep::kStraight);
  Drive(&session, &t, 0.3, 0.0, 3.0, &left, &right);
  EXPECT_NEAR(session.Progress().forward_m, 0.9, 0.02);
  session.Skip();
  EXPECT_EQ(session.step(), SessionStep::kArcs);
  Drive(&session, &t, 0.3, 0.5, 2.0, &left, &right);
  EXPECT_NEAR(session.Progress().arc_left_m, 0.6, 0.02);
  session.Skip();
  EXPECT_EQ(session.step(), SessionStep::kSolve);

  ASSERT_TRUE(session.Advance().ok());  // Runs the solver.
  EXPECT_EQ(session.step(), SessionStep::kReview);
  ASSERT_TRUE(session.result().has_value());
  // Floor only: height, roll, pitch come from the floor; x, y, yaw cannot.
  const auto& k0 = session.result()->kinects[0].parameters;
  EXPECT_TRUE(k0[kZ].Calibrated().has_value());
  EXPECT_NEAR(*k0[kZ].Calibrated(), rig.kinects[0].T_base_kinect.translation().z(), 0.005);
  EXPECT_FALSE(k0[kX].Calibrated().has_value());
  EXPECT_FALSE(k0[kYaw].Calibrated().has_value());

  const std::string file =
      (std::filesystem::temp_directory_path() / "dynamap_session_test_rig.yaml").string();
  std::filesystem::remove(file);
  const robotio::Status save = session.Save(file);
  ASSERT_FALSE(save.ok());
  EXPECT_NE(save.error().message.find("not every parameter is calibrated"), std::string::npos);
  EXPECT_FALSE(std::filesystem::exists(file));
  ASSERT_TRUE(session.Save(file, /*allow_uncalibrated=*/true).ok());
  EXPECT_EQ(session.step(), SessionStep::kDone);
  const auto loaded = robotio::LoadRig(file);
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  EXPECT_EQ(loaded->kinects.size(), 2u);
  std::filesystem::remove(file);
}

// Review names the capture step that would calibrate what is still weak; redoing it counts
// its targets from zero while the data already captured stays in the solve.
TEST(CalibrationSession, ReviewNamesTheStepToRedoAndItsTargetsCountAfresh) {
  const robotio::Rig rig = test::TrueRig();
  SessionConfig config;
  config.floor_frames = 3;
  config.solver.floor_normal_sigma_rad = 0.0005;  // Exact floors: roll/pitch calibrated.
  CalibrationSession session(rig, config);
  std::int64_t t = 0;
  double left = 0.0, right = 0.0;
  for (int i = 0; i < 3; ++i) {
    Drive(&session, &t, 0.0, 0.0, 0.2, &left, &right);
    for (int k = 0; k < 2; ++k) session.AddDepth(FloorFrame(rig.kinects[k], k, t));
  }
  ASSERT_TRUE(session.Advance().ok());
  session.Skip();  // No turning,
  Drive(&session, &t, 0.3, 0.0, 2.0, &left, &right);  // 0.6 m of straight driving,
  session.Skip();
  session.Skip();  // no arcs.
  session.Solve();
  SessionProgress p = session.Progress();
  ASSERT_EQ(p.step, SessionStep::kReview);
  // Roll and pitch come from the floor; kinect0's yaw is the first weak parameter.
  ASSERT_TRUE(p.redo.has_value());
  EXPECT_EQ(*p.redo, SessionStep::kStraight);
  EXPECT_NE(p.instruction.find("'straight'"), std::string::npos) << p.instruction;

  session.Redo(*p.redo);
  p = session.Progress();
  EXPECT_EQ(p.step, SessionStep::kStraight);
  EXPECT_EQ(p.forward_m, 0.0);
  Drive(&session, &t, 0.3, 0.0, 1.0, &left, &right);
  EXPECT_NEAR(session.Progress().forward_m, 0.3, 0.02);

  session.Redo(SessionStep::kFloor);
  EXPECT_EQ(session.Progress().floor_fits, (std::vector<int>{0, 0}));
  EXPECT_EQ(session.capture().kinects[0].floor.size(), 3u);  // Kept for the solve.
}

TEST(CalibrationSession, RedoReturnsToACaptureStepFromReview) {
  CalibrationSession session(test::TrueRig(), SessionConfig{});
  session.Skip();
  session.Skip();
  session.Skip();
  session.Skip();
  EXPECT_EQ(session.step(), SessionStep::kSolve);
  session.Solve();
  EXPECT_EQ(session.step(), SessionStep::kReview);
  session.Redo(SessionStep::kTurn);
  EXPECT_EQ(session.step(), SessionStep::kTurn);
}

}  // namespace
}  // namespace dynamap::calibration
