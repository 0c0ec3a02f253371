// `dynamap calibrate --log` on a recording of the guided sequence driven by hand: the
// calibration room's teleop script recorded by `dynamap record` (160 px), calibrated from
// the operator's guess; the estimates must match the rig the recording was made with.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../robotio/TestPaths.hpp"
#include "../support/CommandRunner.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(CalibrateFromRecording, TheRecordedGuidedSequenceGivesTheRecordingsRig) {
  const std::string dir = test::ScratchDir();
  const auto recorded = test::RunDynamap(
      "record --world " + test::Resource("worlds/calibration_room.yaml") +
          " --duration 89 --width 160 --out " + dir + "/recording",
      dir + "/record.log");
  ASSERT_EQ(recorded.exit_code, 0) << recorded.output;
  const auto calibrated = test::RunDynamap(
      "calibrate --log " + dir + "/recording --rig-guess " +
          test::Resource("rigs/two_kinects_guess.yaml") + " --out " + dir +
          "/calibrated/rig.yaml --allow-uncalibrated",
      dir + "/calibrate.log");
  ASSERT_EQ(calibrated.exit_code, 0) << calibrated.output;
  const auto truth = robotio::LoadRig(dir + "/recording/rig.yaml");
  ASSERT_TRUE(truth.ok()) << truth.error().message;
  const nlohmann::json report = test::ReadJson(dir + "/calibrated/report.json");
  EXPECT_TRUE(report["rig_written"].get<bool>());
  int calibrated_count = 0, checked = 0;
  for (const nlohmann::json& p : report["parameters"]) {
    const std::string name = p["name"];
    if (p["status"] == "calibrated") ++calibrated_count;
    const double value = p["estimate"].is_number() ? p["estimate"].get<double>()
                                                   : p["uncalibrated_value"].get<double>();
    if (name.rfind("kinect", 0) != 0) continue;
    const std::size_t k = name[6] == '0' ? 0 : 1;
    const std::string field = name.substr(name.find('.') + 1);
    const robotio::KinectMount& mount = truth->kinects.at(k);
    const Eigen::Vector3d rpy = robotio::MountRollPitchYaw(mount.T_base_kinect) * 180.0 / kPi;
    const Eigen::Vector3d t = mount.T_base_kinect.translation();
    ++checked;
    if (field == "roll" || field == "pitch" || field == "yaw") {
      const int i = field == "roll" ? 0 : field == "pitch" ? 1 : 2;
      EXPECT_LT(std::abs(std::remainder(value - rpy[i], 360.0)), 0.3) << name;
    } else if (field == "x" || field == "y" || field == "z") {
      const int i = field[0] - 'x';
      EXPECT_LT(std::abs(value - t[i]), 0.005) << name;
    } else if (field == "latency") {
      EXPECT_LT(std::abs(value - mount.latency_s), 0.002) << name;
    }
  }
  EXPECT_EQ(checked, 14);
  // Measured: 15 of 16 (kinect0's yaw weak at 0.15° std dev, 0.14° off; docs/RESULTS.md).
  EXPECT_GE(calibrated_count, 14);
}

}  // namespace
}  // namespace dynamap
