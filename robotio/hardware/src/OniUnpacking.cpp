#include "dynamap/robotio/hardware/OniUnpacking.hpp"

#include "dynamap/robotio/RecordingWriter.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/hardware/OpenNiCamera.hpp"

namespace dynamap::robotio::hardware {
namespace {

Rig LevelCameraRig(const Intrinsics& intrinsics) {
  KinectMount mount;
  mount.id = "camera";
  mount.T_base_kinect = MountPose(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  mount.intrinsics = intrinsics;
  mount.latency_s = 0.0;
  Rig rig;
  rig.kinects.push_back(mount);
  return rig;
}

}  // namespace

Expected<UnpackedFrames> UnpackDepthFrames(DepthCameraInterface& camera, const std::string& what,
                                           std::optional<int> frame_count,
                                           const Intrinsics& intrinsics, const std::string& dir,
                                           const std::string& note,
                                           std::chrono::milliseconds idle_timeout,
                                           const std::function<void(double)>& progress) {
  UnpackedFrames result;
  std::unique_ptr<RecordingWriter> writer;
  const auto expected = [&] {
    return frame_count ? " of the " + std::to_string(*frame_count) + " it holds" : std::string();
  };
  while (!frame_count || static_cast<int>(result.frames) < *frame_count) {
    auto grabbed = camera.Grab(idle_timeout);
    if (!grabbed) {
      if (result.frames == 0) return grabbed.error();
      break;  // The device went away: keep what was written.
    }
    if (!grabbed->has_value()) {
      if (result.frames == 0) {
        return Error{what + ": no depth frame within " + std::to_string(idle_timeout.count()) +
                     " ms (0" + expected() + ")"};
      }
      break;
    }
    DepthFrame frame = std::move(**grabbed);
    if (!writer) {
      result.width = frame.width;
      result.height = frame.height;
      RecordingMeta meta;
      meta.source = "hardware";
      meta.extra["from"] = note;
      auto created = RecordingWriter::Create(
          dir, LevelCameraRig(intrinsics.Scaled(frame.width, frame.height)), meta);
      if (!created) return created.error();
      writer = std::move(*created);
    }
    if (frame.width != result.width || frame.height != result.height) {
      return Error{what + ": frame " + std::to_string(result.frames + 1) + " is " +
                   std::to_string(frame.width) + "x" + std::to_string(frame.height) +
                   ", the first was " + std::to_string(result.width) + "x" +
                   std::to_string(result.height)};
    }
    frame.sensor_id = 0;
    if (auto added = writer->AddDepth(frame); !added) return added.error();
    ++result.frames;
    if (progress && frame_count && *frame_count > 0) {
      progress(static_cast<double>(result.frames) / static_cast<double>(*frame_count));
    }
  }
  return result;
}

Expected<UnpackedFrames> UnpackOniFile(const std::string& oni_file, const std::string& dir,
                                       const std::function<void(double)>& progress) {
  OpenNiCameraConfig config;
  config.device = oni_file;
  auto camera = OpenNiCamera::Open(config);
  if (!camera) return camera.error();
  auto unpacked =
      UnpackDepthFrames(**camera, "OpenNI2 recording " + oni_file, (*camera)->frame_count(),
                        config.intrinsics, dir, oni_file, std::chrono::milliseconds(3000), progress);
  if (!unpacked) {
    // Seen with Debian's OpenNI2 2.2.0.33: the file device opens and counts the frames
    // but never delivers one (docs/HARDWARE.md).
    return Error{unpacked.error().message +
                 "; OpenNI2's file device opened it but played nothing back"};
  }
  return unpacked;
}

}  // namespace dynamap::robotio::hardware
