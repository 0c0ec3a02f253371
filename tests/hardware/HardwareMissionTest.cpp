// An autonomous mission on the robot's devices without the robot: the mission runtime
// with the RMP and MTi emulators on pseudo-terminals, the gamepad's dead-man button as
// js_event records through a FIFO and a scripted Kinect. What must hold: the planner's
// commands reach the base only while the button is held, a lost device stops the base and
// ends the mission, and the maps and report are saved either way.
#include <gtest/gtest.h>
#include <linux/joystick.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "EmulatedRobot.hpp"
#include "dynamap/app/runtime/MissionRuntime.hpp"
#include "dynamap/app/runtime/RobotSources.hpp"
#include "dynamap/robotio/hardware/MonotonicClock.hpp"
#include "dynamap/robotio/hardware/RecordingDevices.hpp"

namespace dynamap::robotio::hardware {
namespace {

namespace fs = std::filesystem;
using test::WaitUntil;

// A wall 1.5 m ahead at 80 × 60 px, about 30 Hz.
class WallCamera final : public DepthCameraInterface {
 public:
  [[nodiscard]] int sensor_id() const override { return 0; }
  Expected<std::optional<DepthFrame>> Grab(std::chrono::milliseconds timeout) override {
    std::this_thread::sleep_for(std::min(timeout, std::chrono::milliseconds(33)));
    DepthFrame frame;
    frame.width = 80;
    frame.height = 60;
    frame.intrinsics = Intrinsics{}.Scaled(80, 60);
    frame.depth_mm.assign(80 * 60, 1500);
    frame.received_ns = MonotonicNanos();
    frame.stamp_ns = frame.received_ns - 30'000'000;
    return std::optional<DepthFrame>(std::move(frame));
  }
};

class HardwareMissionTest : public test::EmulatedRobotTest {
 protected:
  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(EmulatedRobotTest::SetUp());
    ASSERT_NO_FATAL_FAILURE(OpenDevices());
    std::ofstream(dir_ / "rig.yaml")
        << "kinects:\n  - {id: front, translation: [0.1, 0, 0.6], rpy_deg: [0, 10, 0], "
           "latency_s: 0.03}\n";
  }
  void TearDown() override {
    runtime_.reset();  // Before the devices it reads.
    EmulatedRobotTest::TearDown();
  }
  void StartMission() {
    app::runtime::MissionConfig config;
    config.rig_file = (dir_ / "rig.yaml").string();
    config.out_dir = (dir_ / "out").string();
    config.kinect_width = 80;
    config.kinect_height = 60;
    config.max_time_s = 60.0;
    config.area_m = 10.0;
    // As explore --device wires them, with a scripted Kinect.
    app::runtime::DeviceSources sources =
        app::runtime::SourcesFromRobot(devices_, std::make_shared<app::runtime::PadState>());
    sources.cameras.push_back({&camera_, "Kinect front (scripted)"});
    auto runtime = app::runtime::MissionRuntime::CreateOnDevices(config, std::move(sources));
    ASSERT_TRUE(runtime.ok()) << runtime.error().message;
    runtime_ = std::move(runtime).value();
    runtime_->Start();
  }
  bool BaseMoved() const {
    for (const auto& c : rmp_.Commands()) {
      if (c.velocity_counts != 0 || c.turn_counts != 0) return true;
    }
    return false;
  }
  nlohmann::json Report() const {
    std::ifstream in(dir_ / "out" / "report.json");
    return nlohmann::json::parse(in);
  }

  WallCamera camera_;
  std::unique_ptr<app::runtime::MissionRuntime> runtime_;
};

TEST_F(HardwareMissionTest, PlannerCommandsReachTheBaseOnlyWhileTheDeadManIsHeld) {
  ASSERT_NO_FATAL_FAILURE(StartMission());
  // The mission starts by standing still (gyro bias) and then turns to look around; the
  // base must get none of it without the button.
  std::this_thread::sleep_for(std::chrono::milliseconds(3500));
  EXPECT_GT(rmp_.Commands().size(), 100U);
  EXPECT_FALSE(BaseMoved());
  EXPECT_TRUE(runtime_->Snapshot().command.omega != 0.0 || runtime_->Snapshot().command.v != 0.0)
      << "the control worker should want to move by now";

  Pad(JS_EVENT_BUTTON, 4, 1);
  EXPECT_TRUE(WaitUntil([&] { return BaseMoved(); }));
  Pad(JS_EVENT_BUTTON, 4, 0);
  EXPECT_TRUE(WaitUntil([&] {
    const auto commands = rmp_.Commands();
    return commands.back().velocity_counts == 0 && commands.back().turn_counts == 0;
  }));

  runtime_->Stop();
  runtime_->Wait();
  auto report = runtime_->Finish();
  ASSERT_TRUE(report.ok()) << report.error().message;
  EXPECT_GT(report->frames_processed, 30);
  const nlohmann::json json = Report();
  EXPECT_EQ(json["source"], "hardware");
  EXPECT_TRUE(json["collisions"].is_null());
  EXPECT_TRUE(json["ate_rmse_m"].is_null());
  EXPECT_TRUE(json["device_error"].is_null());
  for (const char* file : {"map.ot", "static.bt", "trajectory.tum", "map2d.png", "map2d.pgm"}) {
    EXPECT_TRUE(fs::exists(dir_ / "out" / file)) << file;
  }
  EXPECT_FALSE(fs::exists(dir_ / "out" / "groundtruth.tum"));
  // The base is stopped at the end.
  EXPECT_EQ(rmp_.Commands().back().velocity_counts, 0);
  EXPECT_EQ(rmp_.Commands().back().turn_counts, 0);
}

TEST_F(HardwareMissionTest, UnpluggedBaseEndsTheMissionAndKeepsTheMaps) {
  ASSERT_NO_FATAL_FAILURE(StartMission());
  Pad(JS_EVENT_BUTTON, 4, 1);
  EXPECT_TRUE(WaitUntil([&] { return runtime_->Snapshot().frames_processed > 10; }));
  rmp_.Unplug();
  EXPECT_TRUE(WaitUntil([&] { return runtime_->device_error().has_value(); }));
  runtime_->Wait();  // Ends by itself.
  ASSERT_TRUE(runtime_->device_error().has_value());
  EXPECT_NE(runtime_->device_error()->find("Segway RMP"), std::string::npos)
      << *runtime_->device_error();
  auto report = runtime_->Finish();
  ASSERT_TRUE(report.ok()) << report.error().message;
  const nlohmann::json json = Report();
  EXPECT_NE(json["device_error"].get<std::string>().find(rmp_pty_.slave_path()), std::string::npos);
  EXPECT_TRUE(fs::exists(dir_ / "out" / "map.ot"));
}

TEST_F(HardwareMissionTest, LostPadEndsTheMissionWithTheBaseStopped) {
  ASSERT_NO_FATAL_FAILURE(StartMission());
  Pad(JS_EVENT_BUTTON, 4, 1);
  EXPECT_TRUE(WaitUntil([&] { return BaseMoved(); }, std::chrono::milliseconds(6000)));
  ::close(pad_fd_);
  pad_fd_ = -1;
  EXPECT_TRUE(WaitUntil([&] { return runtime_->device_error().has_value(); }));
  runtime_->Wait();
  EXPECT_NE(runtime_->device_error()->find("gamepad " + pad_path_), std::string::npos)
      << *runtime_->device_error();
  EXPECT_TRUE(WaitUntil([&] {
    const auto commands = rmp_.Commands();
    return commands.back().velocity_counts == 0 && commands.back().turn_counts == 0;
  }));
  ASSERT_TRUE(runtime_->Finish().ok());
}

TEST(HardwareMission, GroundTruthPosesAreRefusedOnTheRobot) {
  app::runtime::MissionConfig config;
  config.poses = app::runtime::PoseSource::kGroundTruth;
  app::runtime::DeviceSources sources;
  struct NoBase : DriveBaseInterface {
    Status Command(const VelocityCommand&) override { return Ok{}; }
    Expected<std::vector<OdometryReading>> ReadOdometry() override {
      return std::vector<OdometryReading>{};
    }
    void Stop() override {}
  } base;
  sources.base = &base;
  sources.deadman = [](std::chrono::milliseconds) -> Expected<bool> { return false; };
  auto runtime = app::runtime::MissionRuntime::CreateOnDevices(config, sources);
  ASSERT_FALSE(runtime.ok());
  EXPECT_NE(runtime.error().message.find("no ground truth"), std::string::npos);
  sources.deadman = nullptr;
  config.poses = app::runtime::PoseSource::kSlam;
  runtime = app::runtime::MissionRuntime::CreateOnDevices(config, sources);
  ASSERT_FALSE(runtime.ok());
  EXPECT_NE(runtime.error().message.find("dead-man"), std::string::npos);
}

}  // namespace
}  // namespace dynamap::robotio::hardware
