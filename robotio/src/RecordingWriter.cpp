#include "dynamap/robotio/RecordingWriter.hpp"

#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "dynamap/robotio/AtomicFile.hpp"
#include "dynamap/robotio/DepthImageIo.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::robotio {

namespace fs = std::filesystem;
namespace rf = recording_files;

namespace {

std::string MetaToYaml(const RecordingMeta& meta) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "format_version" << YAML::Value << meta.format_version;
  out << YAML::Key << "source" << YAML::Value << meta.source;
  out << YAML::Key << "world" << YAML::Value << meta.world;
  out << YAML::Key << "seed" << YAML::Value << meta.seed;
  out << YAML::Key << "duration_s" << YAML::Value << meta.duration_s;
  out << YAML::Key << "extra" << YAML::Value << YAML::BeginMap;
  for (const auto& [key, value] : meta.extra) out << YAML::Key << key << YAML::Value << value;
  out << YAML::EndMap << YAML::EndMap;
  return std::string(out.c_str()) + "\n";
}

const char* HeaderFor(const std::string& index_file) {
  if (index_file == rf::kOdometry) return "# timestamp left_m right_m (cumulative wheel distance)\n";
  if (index_file == rf::kImu) return "# timestamp wx wy wz (rad/s, base frame)\n";
  if (index_file == rf::kGroundTruth) return "# timestamp tx ty tz qx qy qz qw (true T_map_base)\n";
  if (index_file.rfind("labels", 0) == 0) {
    return "# timestamp filename (16-bit labels: object index + 1, bit 15 = dynamic)\n";
  }
  return "# timestamp filename (16-bit depth PNG, metres * 5000)\n";
}

}  // namespace

RecordingWriter::RecordingWriter(std::string dir) : dir_(std::move(dir)) {}

RecordingWriter::~RecordingWriter() {
  for (auto& [name, file] : files_) std::fclose(file);
}

Expected<std::unique_ptr<RecordingWriter>> RecordingWriter::Create(const std::string& dir,
                                                                   const Rig& rig,
                                                                   const RecordingMeta& meta) {
  std::error_code ec;
  if (fs::exists(fs::path(dir) / rf::kMeta, ec)) {
    return Error{dir + ": already holds a recording (meta.yaml exists); choose a new folder"};
  }
  fs::create_directories(dir, ec);
  if (ec) return Error{dir + ": cannot create the recording folder (" + ec.message() + ")"};
  for (std::size_t i = 0; i < rig.kinects.size(); ++i) {
    fs::create_directories(fs::path(dir) / rf::DepthDir(static_cast<int>(i)), ec);
    if (ec) return Error{dir + ": cannot create " + rf::DepthDir(static_cast<int>(i))};
  }
  if (auto status = SaveRig(rig, (fs::path(dir) / rf::kRig).string()); !status) {
    return status.error();
  }
  if (auto status = WriteFileAtomically((fs::path(dir) / rf::kMeta).string(), MetaToYaml(meta));
      !status) {
    return status.error();
  }
  return std::unique_ptr<RecordingWriter>(new RecordingWriter(dir));
}

Status RecordingWriter::AppendLine(const std::string& index_file, const std::string& line) {
  auto it = files_.find(index_file);
  if (it == files_.end()) {
    const std::string path = (fs::path(dir_) / index_file).string();
    std::FILE* file = std::fopen(path.c_str(), "a");
    if (file == nullptr) return Error{path + ": cannot open for appending (" + std::strerror(errno) + ")"};
    std::fputs(HeaderFor(index_file), file);
    it = files_.emplace(index_file, file).first;
  }
  // One fputs + fflush per line: a crash leaves at worst the last line incomplete.
  if (std::fputs((line + "\n").c_str(), it->second) < 0 || std::fflush(it->second) != 0) {
    return Error{(fs::path(dir_) / index_file).string() + ": write failed (" +
                 std::strerror(errno) + ")"};
  }
  return Ok{};
}

Status RecordingWriter::AddDepth(const DepthFrame& frame) {
  if (!frame.Valid()) return Error{dir_ + ": depth frame has inconsistent size"};
  const std::string name =
      rf::DepthDir(frame.sensor_id) + "/" + FormatStamp(frame.received_ns) + ".png";
  std::error_code ec;
  fs::create_directories(fs::path(dir_) / rf::DepthDir(frame.sensor_id), ec);
  const DepthImage image{frame.width, frame.height, MillimetresToTum(frame.depth_mm)};
  if (auto status = WriteDepthPng(image, (fs::path(dir_) / name).string()); !status) return status;
  if (auto status = AppendLine(rf::DepthIndex(frame.sensor_id),
                               FormatStamp(frame.received_ns) + " " + name);
      !status) {
    return status;
  }
  ++depth_frames_;
  return Ok{};
}

Status RecordingWriter::AddLabels(const LabelFrame& labels, std::int64_t received_ns) {
  const std::string name = rf::LabelDir(labels.sensor_id) + "/" + FormatStamp(received_ns) + ".png";
  std::error_code ec;
  fs::create_directories(fs::path(dir_) / rf::LabelDir(labels.sensor_id), ec);
  const DepthImage image{labels.width, labels.height, labels.labels};
  if (auto status = WriteDepthPng(image, (fs::path(dir_) / name).string()); !status) return status;
  return AppendLine(rf::LabelIndex(labels.sensor_id), FormatStamp(received_ns) + " " + name);
}

Status RecordingWriter::AddOdometry(const OdometryReading& r) {
  char buffer[128];
  std::snprintf(buffer, sizeof(buffer), "%s %.9f %.9f", FormatStamp(r.stamp_ns).c_str(),
                r.left_m, r.right_m);
  return AppendLine(rf::kOdometry, buffer);
}

Status RecordingWriter::AddImu(const ImuReading& r) {
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), "%s %.9f %.9f %.9f", FormatStamp(r.stamp_ns).c_str(),
                r.wx, r.wy, r.wz);
  return AppendLine(rf::kImu, buffer);
}

Status RecordingWriter::AddGroundTruth(const StampedPose& pose) {
  return AppendLine(rf::kGroundTruth, FormatTumLine(pose));
}

}  // namespace dynamap::robotio
