// A recorded mission replayed through the mission runtime (the GUI's "recording" source):
// every recorded frame is mapped in lockstep, the run is scored against the recording's
// world and ground truth, and recordings the runtime cannot replay are refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "../robotio/TestPaths.hpp"
#include "SmallOfficeMission.hpp"
#include "dynamap/app/runtime/MissionRuntime.hpp"
#include "dynamap/robotio/RecordingReader.hpp"

namespace dynamap::app::runtime {
namespace {

namespace fs = std::filesystem;

robotio::Expected<MissionReport> RunMission(robotio::Expected<std::unique_ptr<MissionRuntime>> runtime) {
  if (!runtime) return runtime.error();
  (*runtime)->Start();
  (*runtime)->Wait();
  return (*runtime)->Finish();
}

// Records a short mission into `scratch`/recorded and returns the recording's folder.
std::string RecordMission(const std::string& scratch) {
  const std::string out = scratch + "/recorded";
  MissionConfig config = SmallOfficeMission(out);
  config.poses = PoseSource::kGroundTruth;
  config.max_time_s = 8.0;
  config.record = true;
  const auto report = RunMission(MissionRuntime::Create(config));
  EXPECT_TRUE(report) << report.error().message;
  return out + "/recording";
}

TEST(RecordingReplay, EveryRecordedFrameIsMappedAndScored) {
  const std::string scratch = test::ScratchDir();
  const std::string recording = RecordMission(scratch);
  const auto reader = robotio::RecordingReader::Open(recording);
  ASSERT_TRUE(reader) << reader.error().message;
  const auto recorded_frames = static_cast<std::int64_t>(reader->depth_entries().size());
  ASSERT_GT(recorded_frames, 300);

  MissionConfig config;
  config.out_dir = scratch + "/replay";
  config.poses = PoseSource::kSlam;
  auto runtime = MissionRuntime::CreateFromRecording(config, recording);
  ASSERT_TRUE(runtime) << runtime.error().message;
  EXPECT_EQ((*runtime)->config().kinect_width, 160);  // As recorded, not the default.
  EXPECT_NEAR((*runtime)->config().max_time_s, 8.0, 0.05);
  ASSERT_NE((*runtime)->world(), nullptr);  // The recording's world, for scoring.
  (*runtime)->Start();
  (*runtime)->Wait();
  // The live figures a front end shows, with the recording's truth.
  const MissionSnapshot last = (*runtime)->Snapshot();
  EXPECT_NEAR(last.time_limit_s, 8.0, 0.05);
  EXPECT_NEAR(last.sim_time_s, last.time_limit_s, 0.05);
  ASSERT_TRUE(last.ate_so_far_m.has_value());
  ASSERT_TRUE(last.explored_free_fraction.has_value());
  const auto report = (*runtime)->Finish();
  ASSERT_TRUE(report) << report.error().message;
  EXPECT_NEAR(*last.ate_so_far_m, report->ate_rmse_m, 0.01);
  EXPECT_NEAR(*last.explored_free_fraction, report->explored_free_fraction, 0.02);
  EXPECT_EQ(report->frames_delivered, recorded_frames);
  EXPECT_EQ(report->frames_dropped, 0);
  // All but a last lone frame, which waits for the other Kinect's frame of its instant.
  EXPECT_GE(report->frames_processed, recorded_frames - 1);
  EXPECT_GT(report->registrations_accepted, 100);
  ASSERT_TRUE(std::isfinite(report->ate_rmse_m));
  EXPECT_LT(report->ate_rmse_m, 0.1);
  EXPECT_GT(report->static_accuracy, 0.8);
  EXPECT_GT(report->explored_free_fraction, 0.0);
  EXPECT_EQ(report->collisions, 0);
  for (const char* file : {"map.ot", "trajectory.tum", "groundtruth.tum", "map2d.png"}) {
    EXPECT_TRUE(fs::exists(fs::path(config.out_dir) / file)) << file;
  }
  EXPECT_FALSE(fs::exists(fs::path(config.out_dir) / "recording"));
}

TEST(RecordingReplay, ACalibratedRigReplacesTheRecordedExtrinsics) {
  const std::string out = test::ScratchDir();
  std::ofstream(out + "/other_rig.yaml")
      << "kinects:\n  - {id: somewhere_else, translation: [0, 0, 0.5], rpy_deg: [0, 0, 0]}\n";
  MissionConfig config;
  config.out_dir = out + "/run";
  config.rig_file = out + "/other_rig.yaml";
  const auto runtime = MissionRuntime::CreateFromRecording(config, RecordMission(out));
  ASSERT_FALSE(runtime);
  EXPECT_NE(runtime.error().message.find("no Kinect with id 'kinect0'"), std::string::npos)
      << runtime.error().message;
}

TEST(RecordingReplay, RecordingsItCannotReplayAreRefusedByName) {
  const std::string out = test::ScratchDir();
  MissionConfig config;
  config.out_dir = out + "/run";
  auto runtime = MissionRuntime::CreateFromRecording(config, out + "/absent");
  ASSERT_FALSE(runtime);
  EXPECT_NE(runtime.error().message.find(out + "/absent"), std::string::npos);

  // A TUM sequence: depth only, no odometry.
  fs::create_directories(out + "/tum/depth");
  fs::copy_file(test::SharedData("tum/TUM_depth.png"), out + "/tum/depth/1.000000.png");
  std::ofstream(out + "/tum/depth.txt") << "1.000000 depth/1.000000.png\n";
  runtime = MissionRuntime::CreateFromRecording(config, out + "/tum");
  ASSERT_FALSE(runtime);
  EXPECT_NE(runtime.error().message.find("no odometry.txt"), std::string::npos)
      << runtime.error().message;
  EXPECT_NE(runtime.error().message.find("dynamap map"), std::string::npos);
}

}  // namespace
}  // namespace dynamap::app::runtime
