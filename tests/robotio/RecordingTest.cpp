#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

#include "TestPaths.hpp"
#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"

namespace dynamap::robotio {
namespace {

Rig SmallRig() {
  Rig rig;
  for (int i = 0; i < 2; ++i) {
    KinectMount m;
    m.id = "kinect" + std::to_string(i);
    m.intrinsics = Intrinsics{}.Scaled(64, 48);
    m.T_base_kinect = MountPose({0.0, 0.0, 0.6 - 0.14 * i}, {M_PI, 0.1, 0.5 - i});
    rig.kinects.push_back(m);
  }
  return rig;
}

DepthFrame RandomFrame(int sensor, std::int64_t capture_ns, std::mt19937& rng) {
  DepthFrame f;
  f.sensor_id = sensor;
  f.stamp_ns = capture_ns;
  f.received_ns = capture_ns + 100'000'000;
  f.width = 64;
  f.height = 48;
  f.intrinsics = Intrinsics{}.Scaled(64, 48);
  std::uniform_int_distribution<int> depth(0, 9000);
  for (int i = 0; i < 64 * 48; ++i) f.depth_mm.push_back(static_cast<std::uint16_t>(depth(rng)));
  return f;
}

TEST(Recording, WriteThenReadGivesBitExactDataBack) {
  const std::string dir = test::ScratchDir() + "/rec";
  std::mt19937 rng(7);
  std::vector<DepthFrame> written;
  {
    RecordingMeta meta;
    meta.world = "office.yaml";
    meta.seed = 42;
    auto writer = RecordingWriter::Create(dir, SmallRig(), meta);
    ASSERT_TRUE(writer.ok()) << writer.error().message;
    for (int k = 0; k < 4; ++k) {
      for (int s = 0; s < 2; ++s) {
        written.push_back(RandomFrame(s, 1'000'000'000LL + k * 33'333'333LL + s * 1000, rng));
        ASSERT_TRUE((*writer)->AddDepth(written.back()).ok());
        LabelFrame labels;
        labels.sensor_id = s;
        labels.width = 64;
        labels.height = 48;
        labels.labels.assign(64 * 48, static_cast<std::uint16_t>(3 | LabelFrame::kDynamicBit));
        ASSERT_TRUE((*writer)->AddLabels(labels, written.back().received_ns).ok());
      }
      ASSERT_TRUE((*writer)->AddOdometry({k * 20'000'000LL, 0.01 * k, 0.012 * k}).ok());
      ASSERT_TRUE((*writer)->AddImu({k * 10'000'000LL, 0.0, 0.0, 0.25 * k}).ok());
      ASSERT_TRUE((*writer)->AddGroundTruth(ToStampedPose(k * 10'000'000LL, {0.1 * k, 0.0, 0.2})).ok());
    }
  }
  auto reader = RecordingReader::Open(dir);
  ASSERT_TRUE(reader.ok()) << reader.error().message;
  EXPECT_TRUE(reader->warnings().empty());
  EXPECT_EQ(reader->meta().seed, 42u);
  EXPECT_EQ(reader->meta().world, "office.yaml");
  ASSERT_EQ(reader->rig().kinects.size(), 2u);
  ASSERT_EQ(reader->depth_entries().size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    auto frame = reader->LoadDepth(reader->depth_entries()[i]);
    ASSERT_TRUE(frame.ok()) << frame.error().message;
    EXPECT_EQ(frame->sensor_id, written[i].sensor_id);
    EXPECT_EQ(frame->received_ns, written[i].received_ns);
    EXPECT_EQ(frame->stamp_ns, written[i].stamp_ns);  // Rig latency 0.1 s.
    EXPECT_EQ(frame->depth_mm, written[i].depth_mm);
    auto labels = reader->LoadLabels(reader->depth_entries()[i]);
    ASSERT_TRUE(labels.has_value());
    EXPECT_TRUE(LabelFrame::IsDynamic(labels->labels[0]));
    EXPECT_EQ(LabelFrame::ObjectIndex(labels->labels[0]), 2);
  }
  ASSERT_EQ(reader->odometry().size(), 4u);
  EXPECT_DOUBLE_EQ(reader->odometry()[3].right_m, 0.036);
  ASSERT_EQ(reader->imu().size(), 4u);
  EXPECT_DOUBLE_EQ(reader->imu()[2].wz, 0.5);
  ASSERT_EQ(reader->ground_truth().size(), 4u);
  EXPECT_NEAR(reader->ground_truth()[3].pose.translation().x(), 0.3, 1e-9);
}

// Re-mapping an old recording with a new calibration: poses and latencies come from the
// new rig (matched by id), intrinsics stay the recorded ones.
TEST(Recording, ExtrinsicsFromAnotherRigReplaceTheRecordedOnes) {
  const std::string dir = test::ScratchDir() + "/rec";
  std::mt19937 rng(3);
  const DepthFrame written = RandomFrame(1, 2'000'000'000LL, rng);
  {
    auto writer = RecordingWriter::Create(dir, SmallRig(), {});
    ASSERT_TRUE(writer.ok()) << writer.error().message;
    ASSERT_TRUE((*writer)->AddDepth(written).ok());
  }
  auto reader = RecordingReader::Open(dir);
  ASSERT_TRUE(reader.ok()) << reader.error().message;

  Rig calibrated = SmallRig();
  std::swap(calibrated.kinects[0], calibrated.kinects[1]);  // Matched by id, not order.
  calibrated.kinects[0].T_base_kinect = MountPose({0.1, 0.02, 0.5}, {M_PI, 0.2, -0.4});
  calibrated.kinects[0].latency_s = 0.08;
  calibrated.kinects[0].intrinsics = Intrinsics{};  // 640 x 480: must not be taken.
  ASSERT_TRUE(reader->UseExtrinsics(calibrated, "new_rig.yaml").ok());
  const KinectMount& mount = reader->rig().kinects[1];
  EXPECT_EQ(mount.id, "kinect1");
  EXPECT_TRUE(mount.T_base_kinect.isApprox(calibrated.kinects[0].T_base_kinect));
  EXPECT_DOUBLE_EQ(mount.latency_s, 0.08);
  EXPECT_EQ(mount.intrinsics.width, 64);
  auto frame = reader->LoadDepth(reader->depth_entries()[0]);
  ASSERT_TRUE(frame.ok()) << frame.error().message;
  EXPECT_EQ(frame->stamp_ns, written.received_ns - 80'000'000LL);

  Rig other = SmallRig();
  other.kinects[1].id = "kinect7";
  const Status missing = reader->UseExtrinsics(other, "other_rig.yaml");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.error().message.find("other_rig.yaml"), std::string::npos);
  EXPECT_NE(missing.error().message.find("'kinect1'"), std::string::npos);
}

TEST(Recording, CreatingOverAnExistingRecordingIsRefused) {
  const std::string dir = test::ScratchDir() + "/rec";
  ASSERT_TRUE(RecordingWriter::Create(dir, SmallRig(), {}).ok());
  auto second = RecordingWriter::Create(dir, SmallRig(), {});
  ASSERT_FALSE(second.ok());
  EXPECT_NE(second.error().message.find("already holds a recording"), std::string::npos);
}

TEST(Recording, IncompleteLastLinesAreDroppedWithAWarning) {
  const std::string dir = test::ScratchDir() + "/rec";
  std::mt19937 rng(1);
  {
    auto writer = RecordingWriter::Create(dir, SmallRig(), {});
    ASSERT_TRUE(writer.ok());
    for (int k = 0; k < 3; ++k) {
      ASSERT_TRUE((*writer)->AddDepth(RandomFrame(0, k * 33'000'000LL, rng)).ok());
      ASSERT_TRUE((*writer)->AddOdometry({k * 20'000'000LL, 0.01 * k, 0.01 * k}).ok());
    }
  }
  // What a crash mid-write leaves: half an index line, half an odometry line.
  std::ofstream(dir + "/depth.txt", std::ios::app) << "0.1990000 depth/0.19";
  std::ofstream(dir + "/odometry.txt", std::ios::app) << "0.060000000 0.03";
  auto reader = RecordingReader::Open(dir);
  ASSERT_TRUE(reader.ok()) << reader.error().message;
  EXPECT_EQ(reader->depth_entries().size(), 3u);
  EXPECT_EQ(reader->odometry().size(), 3u);
  std::vector<std::string> cut_off;
  for (const auto& w : reader->warnings()) {
    if (w.find("cut off") != std::string::npos) cut_off.push_back(w);
  }
  ASSERT_EQ(cut_off.size(), 2u);
  EXPECT_NE(cut_off[0].find("depth.txt: line 5"), std::string::npos) << cut_off[0];
  EXPECT_NE(cut_off[1].find("odometry.txt: line 5"), std::string::npos) << cut_off[1];
}

TEST(Recording, ProcessKilledWhileRecordingReadsBackUpToItsLastWholeFrame) {
  const std::string dir = test::ScratchDir() + "/rec";
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::mt19937 rng(3);
    auto writer = RecordingWriter::Create(dir, SmallRig(), {});
    if (!writer.ok()) _exit(1);
    for (std::int64_t k = 0;; ++k) {
      (void)(*writer)->AddDepth(RandomFrame(static_cast<int>(k % 2), k * 16'000'000LL, rng));
      (void)(*writer)->AddOdometry({k * 16'000'000LL, 0.001 * k, 0.001 * k});
    }
  }
  // Let it write a few dozen frames, then kill it without warning.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
  while (std::chrono::steady_clock::now() < deadline) {
    std::ifstream index(dir + "/depth1.txt");
    const auto lines = std::count(std::istreambuf_iterator<char>(index),
                                  std::istreambuf_iterator<char>(), '\n');
    if (lines > 20) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));

  auto reader = RecordingReader::Open(dir);
  ASSERT_TRUE(reader.ok()) << reader.error().message;
  ASSERT_GT(reader->depth_entries().size(), 20u);
  // Every indexed frame is whole: the image was in place before its index line.
  for (const DepthEntry& entry : reader->depth_entries()) {
    auto frame = reader->LoadDepth(entry);
    ASSERT_TRUE(frame.ok()) << frame.error().message;
    EXPECT_EQ(frame->depth_mm.size(), 64u * 48u);
  }
}

TEST(Recording, FolderWithoutARecordingIsAClearError) {
  const std::string dir = test::ScratchDir();
  auto reader = RecordingReader::Open(dir);
  ASSERT_FALSE(reader.ok());
  EXPECT_NE(reader.error().message.find("not a recording"), std::string::npos);
  EXPECT_NE(reader.error().message.find(dir), std::string::npos);
}

TEST(Recording, MalformedMiddleLineIsAnErrorNamingFileAndLine) {
  const std::string dir = test::ScratchDir() + "/rec";
  {
    auto writer = RecordingWriter::Create(dir, SmallRig(), {});
    ASSERT_TRUE(writer.ok());
    ASSERT_TRUE((*writer)->AddOdometry({0, 0.0, 0.0}).ok());
  }
  std::ofstream(dir + "/odometry.txt", std::ios::app) << "0.02 abc 0.1\n0.04 0.1 0.1\n";
  auto reader = RecordingReader::Open(dir);
  ASSERT_FALSE(reader.ok());
  EXPECT_NE(reader.error().message.find("odometry.txt: line 3"), std::string::npos)
      << reader.error().message;
}

TEST(Recording, OpensARealTumSequenceFolderWithoutRigOrMeta) {
  const std::string dir = test::ScratchDir();
  std::filesystem::create_directories(dir + "/depth");
  std::filesystem::copy_file(test::SharedData("tum/TUM_depth.png"),
                             dir + "/depth/1305031102.160407.png");
  std::ofstream(dir + "/depth.txt") << "# depth maps\n# file: 'rgbd_dataset_freiburg1_xyz.bag'\n"
                                    << "# timestamp filename\n"
                                    << "1305031102.160407 depth/1305031102.160407.png\n";
  std::filesystem::copy_file(test::SharedData("tum/fr2_desk_groundtruth.txt"),
                             dir + "/groundtruth.txt");
  auto reader = RecordingReader::Open(dir);
  ASSERT_TRUE(reader.ok()) << reader.error().message;
  EXPECT_TRUE(reader->is_tum_sequence());
  ASSERT_EQ(reader->depth_entries().size(), 1u);
  EXPECT_EQ(reader->depth_entries()[0].received_ns, 1305031102160407000LL);
  EXPECT_GT(reader->ground_truth().size(), 2000u);
  auto frame = reader->LoadDepth(reader->depth_entries()[0]);
  ASSERT_TRUE(frame.ok()) << frame.error().message;
  EXPECT_EQ(frame->width, 640);
}

}  // namespace
}  // namespace dynamap::robotio
