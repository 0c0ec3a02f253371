// The hardware recording loop end to end without hardware: the RMP and MTi emulators on
// pseudo-terminals, the gamepad as js_event records through a FIFO, depth from a scripted
// camera or OpenNI2's software device; the recording is read back with RecordingReader.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <linux/joystick.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <future>
#include <thread>

#include "EmulatedRobot.hpp"
#include "PtyPair.hpp"
#include "RmpEmulator.hpp"
#include "XsensEmulator.hpp"
#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"
#include "dynamap/robotio/hardware/MonotonicClock.hpp"
#include "dynamap/robotio/hardware/RecordingDevices.hpp"
#include "dynamap/robotio/hardware/RecordingLoop.hpp"

namespace dynamap::robotio::hardware {
namespace {

namespace fs = std::filesystem;
using test::PtyPair;
using test::RmpEmulator;
using test::WaitUntil;
using test::XsensEmulator;

constexpr double kCountsPerM = 40181.0;  // RmpConfig's default.

// Depth frames of a fixed pattern at about 30 Hz; after `frames_before_silence` frames it
// goes quiet (a camera whose USB link died without an error).
class ScriptedCamera final : public DepthCameraInterface {
 public:
  ScriptedCamera(int sensor_id, int frames_before_silence)
      : sensor_id_(sensor_id), limit_(frames_before_silence) {}
  [[nodiscard]] int sensor_id() const override { return sensor_id_; }
  Expected<std::optional<DepthFrame>> Grab(std::chrono::milliseconds timeout) override {
    if (limit_ >= 0 && sent_ >= limit_) {
      std::this_thread::sleep_for(timeout);
      return std::optional<DepthFrame>{};
    }
    std::this_thread::sleep_for(std::min(timeout, std::chrono::milliseconds(33)));
    DepthFrame frame;
    frame.sensor_id = sensor_id_;
    frame.width = 16;
    frame.height = 12;
    frame.depth_mm.assign(16 * 12, static_cast<std::uint16_t>(1000 + sent_));
    frame.received_ns = MonotonicNanos();
    frame.stamp_ns = frame.received_ns - 30'000'000;
    ++sent_;
    return std::optional<DepthFrame>(std::move(frame));
  }

 private:
  int sensor_id_;
  int limit_;
  int sent_ = 0;
};

Rig OneKinectRig(int width, int height) {
  Rig rig;
  rig.kinects.emplace_back();
  rig.kinects[0].intrinsics = Intrinsics{}.Scaled(width, height);
  return rig;
}

// Opening: a missing, silent or unnamed device is an Error that names it.

TEST(RecordingDevices, MissingBaseNamesTheSerialPort) {
  DriveDevicesConfig config;
  config.rmp.device = "/dev/ttyUSB-dynamap-missing";
  const auto devices = OpenDriveDevices(config);
  ASSERT_FALSE(devices.ok());
  EXPECT_NE(devices.error().message.find("Segway RMP"), std::string::npos);
  EXPECT_NE(devices.error().message.find("/dev/ttyUSB-dynamap-missing"), std::string::npos);
  EXPECT_NE(devices.error().message.find("No such file"), std::string::npos);
}

TEST(RecordingDevices, SilentBaseIsAnErrorBeforeRecording) {
  PtyPair pty;  // Nothing answers on the far end: a base that is switched off.
  DriveDevicesConfig config;
  config.rmp.device = pty.slave_path();
  config.first_data_timeout_ms = 200;
  const auto devices = OpenDriveDevices(config);
  ASSERT_FALSE(devices.ok());
  EXPECT_NE(devices.error().message.find("Segway RMP on " + pty.slave_path()), std::string::npos);
  EXPECT_NE(devices.error().message.find("no status message"), std::string::npos)
      << devices.error().message;
}

TEST(RecordingDevices, MissingGyroAndMissingPadAreNamed) {
  PtyPair rmp_pty;
  RmpEmulator rmp(rmp_pty);
  DriveDevicesConfig config;
  config.rmp.device = rmp_pty.slave_path();
  config.imu.emplace();
  config.imu->device = "/dev/dynamap-missing-imu";
  auto devices = OpenDriveDevices(config);
  ASSERT_FALSE(devices.ok());
  EXPECT_NE(devices.error().message.find("Xsens IMU"), std::string::npos);
  EXPECT_NE(devices.error().message.find("/dev/dynamap-missing-imu"), std::string::npos);

  config.imu.reset();
  config.pad.device = "/dev/input/js-dynamap-missing";
  devices = OpenDriveDevices(config);
  ASSERT_FALSE(devices.ok());
  EXPECT_NE(devices.error().message.find("gamepad /dev/input/js-dynamap-missing"),
            std::string::npos)
      << devices.error().message;
}

TEST(RecordingDevices, MissingKinectIsAnErrorNamingItsRigEntry) {
  if (ListOpenNiDevices().ok()) {
    // Also the case once OpenNI2's software device was opened earlier in this process;
    // ctest runs every test in a process of its own.
    GTEST_SKIP() << "OpenNI2 lists a camera";
  }
  auto configs = CameraConfigsForRig(OneKinectRig(640, 480), {});
  ASSERT_TRUE(configs.ok()) << configs.error().message;
  const auto cameras = OpenRecordingCameras(*configs);
  ASSERT_FALSE(cameras.ok());
  EXPECT_NE(cameras.error().message.find("Kinect kinect0"), std::string::npos);
  EXPECT_NE(cameras.error().message.find("no depth camera"), std::string::npos)
      << cameras.error().message;
}

TEST(RecordingDevices, TwoKinectRigNeedsEachCameraNamed) {
  Rig rig = OneKinectRig(640, 480);
  rig.kinects.push_back(rig.kinects[0]);
  rig.kinects[1].id = "kinect1";
  auto configs = CameraConfigsForRig(rig, {});
  ASSERT_FALSE(configs.ok());
  EXPECT_NE(configs.error().message.find("2 Kinects"), std::string::npos);
  configs = CameraConfigsForRig(rig, {"serial:A"});
  ASSERT_FALSE(configs.ok());
  EXPECT_NE(configs.error().message.find("1 camera(s) named for a rig with 2"), std::string::npos);
  configs = CameraConfigsForRig(rig, {"serial:A", "serial:B"});
  ASSERT_TRUE(configs.ok()) << configs.error().message;
  EXPECT_EQ((*configs)[1].camera.sensor_id, 1);
  EXPECT_EQ((*configs)[1].camera.device, "serial:B");
  EXPECT_EQ((*configs)[1].name, "Kinect kinect1 (serial:B)");
}

TEST(RecordingDevices, CameraIndexBeyondTheListedDevicesIsAnError) {
  const auto configs = CameraConfigsForRig(OneKinectRig(640, 480), {"7"});
  ASSERT_FALSE(configs.ok());
  EXPECT_EQ(configs.error().message.rfind("camera 7: ", 0), 0U) << configs.error().message;
}

class RecordingLoopTest : public test::EmulatedRobotTest {
 protected:
  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(EmulatedRobotTest::SetUp());
    rmp_.SetWheelCounts(5000, -7000);  // The base's counters do not start at zero.
    imu_.SetRate(0.0F, 0.0F, 0.25F);
  }
  std::unique_ptr<RecordingWriter> Writer(const Rig& rig) {
    RecordingMeta meta;
    meta.source = "hardware";
    auto writer = RecordingWriter::Create((dir_ / "rec").string(), rig, meta);
    EXPECT_TRUE(writer.ok()) << (writer.ok() ? "" : writer.error().message);
    return writer.ok() ? std::move(writer).value() : nullptr;
  }
  std::future<RecordingLoopResult> Start(RecordingWriter& writer, const RecordingSources& sources) {
    loop_.origin_ns = MonotonicNanos();
    return std::async(std::launch::async, [this, &writer, sources] {
      return RunRecordingLoop(loop_, sources, writer, interrupt_,
                              [this](const RecordingProgress& p) {
                                if (p.deadman_held) saw_deadman_ = true;
                                odometry_written_ = p.odometry;
                                imu_written_ = p.imu;
                              });
    });
  }
  RecordingReader Read() {
    auto reader = RecordingReader::Open((dir_ / "rec").string());
    EXPECT_TRUE(reader.ok()) << (reader.ok() ? "" : reader.error().message);
    return std::move(reader).value();
  }

  RecordingLoopConfig loop_;
  std::atomic<bool> interrupt_{false};
  std::atomic<bool> saw_deadman_{false};
  std::atomic<std::uint64_t> odometry_written_{0};
  std::atomic<std::uint64_t> imu_written_{0};
};

TEST_F(RecordingLoopTest, DrivesWithThePadRecordsOdometryAndGyroAndEndsOnStart) {
  ASSERT_NO_FATAL_FAILURE(OpenDevices());
  auto writer = Writer(OneKinectRig(640, 480));
  ASSERT_NE(writer, nullptr);
  auto running = Start(*writer, devices_.Sources());

  Pad(JS_EVENT_BUTTON, 4, 1);     // Dead-man held...
  Pad(JS_EVENT_AXIS, 1, -32767);  // ...and full stick forward: 0.5 m/s = 201 counts.
  EXPECT_TRUE(WaitUntil([&] {
    const auto commands = rmp_.Commands();
    return !commands.empty() && commands.back().velocity_counts == 201;
  }));
  EXPECT_TRUE(WaitUntil([&] { return odometry_written_ > 0; }));  // Some readings at rest.
  rmp_.SetWheelCounts(5000 + static_cast<std::int32_t>(kCountsPerM),
                      -7000 + static_cast<std::int32_t>(2 * kCountsPerM));
  // Both streams past 20 readings (on a loaded machine the gyro's may lag the wheels').
  EXPECT_TRUE(WaitUntil([&] { return odometry_written_ > 20 && imu_written_ > 20; }));
  Pad(JS_EVENT_BUTTON, 7, 1);  // Start.
  ASSERT_EQ(running.wait_for(std::chrono::seconds(3)), std::future_status::ready);
  const RecordingLoopResult result = running.get();

  EXPECT_EQ(result.end, RecordingEnd::kFinishButton);
  EXPECT_FALSE(result.error.has_value()) << result.error->message;
  EXPECT_TRUE(saw_deadman_);
  // The base is stopped once the loop is over.
  EXPECT_TRUE(WaitUntil([&] {
    const auto commands = rmp_.Commands();
    return !commands.empty() && commands.back().velocity_counts == 0;
  }));

  writer.reset();
  const RecordingReader reader = Read();
  ASSERT_EQ(reader.odometry().size(), result.totals.odometry);
  ASSERT_EQ(reader.imu().size(), result.totals.imu);
  ASSERT_GT(reader.odometry().size(), 20U);
  ASSERT_GT(reader.imu().size(), 20U);
  // Wheel travel from zero at the start: 1 m left, 2 m right at the end.
  EXPECT_NEAR(reader.odometry().back().left_m, 1.0, 1e-6);
  EXPECT_NEAR(reader.odometry().back().right_m, 2.0, 1e-6);
  EXPECT_NEAR(reader.odometry().front().left_m, 0.0, 1e-6);
  for (const ImuReading& r : reader.imu()) EXPECT_NEAR(r.wz, 0.25, 1e-6);
  // Stamps start at the recording's origin and never go back.
  EXPECT_GE(reader.odometry().front().stamp_ns, 0);
  EXPECT_GE(reader.imu().front().stamp_ns, 0);
  for (std::size_t i = 1; i < reader.odometry().size(); ++i) {
    EXPECT_GE(reader.odometry()[i].stamp_ns, reader.odometry()[i - 1].stamp_ns);
  }
  EXPECT_LT(reader.odometry().back().stamp_ns,
            static_cast<std::int64_t>(result.totals.elapsed_s * 1e9) + 1);
  EXPECT_EQ(reader.meta().source, "hardware");
}

TEST_F(RecordingLoopTest, UnpluggedBaseEndsTheRecordingNamingItAndKeepsWhatArrived) {
  ASSERT_NO_FATAL_FAILURE(OpenDevices());
  auto writer = Writer(OneKinectRig(640, 480));
  ASSERT_NE(writer, nullptr);
  auto running = Start(*writer, devices_.Sources());
  EXPECT_TRUE(WaitUntil([&] { return odometry_written_ > 10; }));
  rmp_.Unplug();
  ASSERT_EQ(running.wait_for(std::chrono::seconds(3)), std::future_status::ready);
  const RecordingLoopResult result = running.get();

  EXPECT_EQ(result.end, RecordingEnd::kDeviceError);
  ASSERT_TRUE(result.error.has_value());
  EXPECT_NE(result.error->message.find("Segway RMP"), std::string::npos) << result.error->message;
  EXPECT_NE(result.error->message.find(rmp_pty_.slave_path()), std::string::npos);
  writer.reset();
  const RecordingReader reader = Read();
  EXPECT_EQ(reader.odometry().size(), result.totals.odometry);
  EXPECT_GT(reader.odometry().size(), 10U);
  EXPECT_EQ(reader.imu().size(), result.totals.imu);
  EXPECT_GT(reader.imu().size(), 0U);
}

TEST_F(RecordingLoopTest, UnpluggedPadStopsTheBaseAndEndsTheRecording) {
  ASSERT_NO_FATAL_FAILURE(OpenDevices());
  auto writer = Writer(OneKinectRig(640, 480));
  ASSERT_NE(writer, nullptr);
  auto running = Start(*writer, devices_.Sources());
  Pad(JS_EVENT_BUTTON, 4, 1);
  Pad(JS_EVENT_AXIS, 1, -32767);
  EXPECT_TRUE(WaitUntil([&] {
    const auto commands = rmp_.Commands();
    return !commands.empty() && commands.back().velocity_counts == 201;
  }));
  ::close(pad_fd_);
  pad_fd_ = -1;
  ASSERT_EQ(running.wait_for(std::chrono::seconds(3)), std::future_status::ready);
  const RecordingLoopResult result = running.get();
  EXPECT_EQ(result.end, RecordingEnd::kDeviceError);
  ASSERT_TRUE(result.error.has_value());
  EXPECT_NE(result.error->message.find("gamepad " + pad_path_), std::string::npos)
      << result.error->message;
  EXPECT_TRUE(WaitUntil([&] { return rmp_.Commands().back().velocity_counts == 0; }));
}

TEST_F(RecordingLoopTest, InterruptEndsTheRecordingCleanly) {
  ASSERT_NO_FATAL_FAILURE(OpenDevices());
  auto writer = Writer(OneKinectRig(640, 480));
  ASSERT_NE(writer, nullptr);
  auto running = Start(*writer, devices_.Sources());
  EXPECT_TRUE(WaitUntil([&] { return odometry_written_ > 5; }));
  interrupt_ = true;
  ASSERT_EQ(running.wait_for(std::chrono::seconds(3)), std::future_status::ready);
  const RecordingLoopResult result = running.get();
  EXPECT_EQ(result.end, RecordingEnd::kInterrupted);
  EXPECT_FALSE(result.error.has_value());
  writer.reset();
  EXPECT_EQ(Read().odometry().size(), result.totals.odometry);
}

TEST_F(RecordingLoopTest, EveryCameraFrameIsWrittenUntilTheDurationEnds) {
  config_.imu.reset();  // Recording without a gyro is allowed.
  ASSERT_NO_FATAL_FAILURE(OpenDevices());
  Rig rig = OneKinectRig(16, 12);
  rig.kinects.push_back(rig.kinects[0]);
  rig.kinects[1].id = "kinect1";
  auto writer = Writer(rig);
  ASSERT_NE(writer, nullptr);
  ScriptedCamera first(0, -1);
  ScriptedCamera second(1, -1);
  RecordingSources sources = devices_.Sources();
  sources.cameras = {{&first, "Kinect kinect0"}, {&second, "Kinect kinect1"}};
  loop_.duration_s = 0.6;
  auto running = Start(*writer, sources);
  ASSERT_EQ(running.wait_for(std::chrono::seconds(3)), std::future_status::ready);
  const RecordingLoopResult result = running.get();

  EXPECT_EQ(result.end, RecordingEnd::kDuration);
  EXPECT_FALSE(result.error.has_value());
  EXPECT_GE(result.totals.elapsed_s, 0.6);
  ASSERT_EQ(result.totals.frames.size(), 2U);
  EXPECT_GT(result.totals.frames[0], 5U);
  EXPECT_GT(result.totals.frames[1], 5U);
  EXPECT_EQ(result.totals.dropped_frames, 0U);
  writer.reset();
  const RecordingReader reader = Read();
  EXPECT_EQ(reader.depth_entries().size(), result.totals.frames[0] + result.totals.frames[1]);
  EXPECT_TRUE(reader.imu().empty());
  ASSERT_FALSE(reader.depth_entries().empty());
  const auto frame = reader.LoadDepth(reader.depth_entries().front());
  ASSERT_TRUE(frame.ok()) << frame.error().message;
  EXPECT_EQ(frame->width, 16);
  EXPECT_EQ(frame->At(3, 3), 1000);  // The first frame's value.
  EXPECT_GE(reader.depth_entries().front().received_ns, 0);
}

TEST_F(RecordingLoopTest, CameraThatStopsDeliveringIsADeviceErrorNamingIt) {
  ASSERT_NO_FATAL_FAILURE(OpenDevices());
  auto writer = Writer(OneKinectRig(16, 12));
  ASSERT_NE(writer, nullptr);
  ScriptedCamera camera(0, 3);
  RecordingSources sources = devices_.Sources();
  sources.cameras = {{&camera, "Kinect kinect0 (serial:TEST)"}};
  loop_.camera_silence_ms = 200;
  auto running = Start(*writer, sources);
  ASSERT_EQ(running.wait_for(std::chrono::seconds(3)), std::future_status::ready);
  const RecordingLoopResult result = running.get();
  EXPECT_EQ(result.end, RecordingEnd::kDeviceError);
  ASSERT_TRUE(result.error.has_value());
  EXPECT_NE(result.error->message.find("Kinect kinect0 (serial:TEST): no depth frame"),
            std::string::npos)
      << result.error->message;
  writer.reset();
  EXPECT_EQ(Read().depth_entries().size(), 3U);
}

TEST_F(RecordingLoopTest, OpenNiSoftwareCameraFramesAreRecorded) {
  ASSERT_NO_FATAL_FAILURE(OpenDevices());
  const Rig rig = OneKinectRig(320, 240);  // The Dummy device's only mode.
  auto configs = CameraConfigsForRig(rig, {"Dummy"});
  ASSERT_TRUE(configs.ok()) << configs.error().message;
  auto cameras = OpenRecordingCameras(*configs);
  ASSERT_TRUE(cameras.ok()) << cameras.error().message;
  devices_.cameras = std::move(cameras).value();
  devices_.camera_names = {(*configs)[0].name};
  auto writer = Writer(rig);
  ASSERT_NE(writer, nullptr);
  loop_.duration_s = 0.5;
  auto running = Start(*writer, devices_.Sources());
  ASSERT_EQ(running.wait_for(std::chrono::seconds(3)), std::future_status::ready);
  const RecordingLoopResult result = running.get();
  EXPECT_EQ(result.end, RecordingEnd::kDuration);
  EXPECT_FALSE(result.error.has_value()) << result.error->message;
  writer.reset();
  const RecordingReader reader = Read();
  ASSERT_GT(reader.depth_entries().size(), 3U);
  const auto frame = reader.LoadDepth(reader.depth_entries().back());
  ASSERT_TRUE(frame.ok()) << frame.error().message;
  EXPECT_EQ(frame->width, 320);
}

}  // namespace
}  // namespace dynamap::robotio::hardware
