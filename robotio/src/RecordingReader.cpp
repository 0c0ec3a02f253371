#include "dynamap/robotio/RecordingReader.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <limits>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "dynamap/robotio/ConfigReader.hpp"
#include "dynamap/robotio/DepthImageIo.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::robotio {

namespace fs = std::filesystem;
namespace rf = recording_files;

namespace {

struct IndexLine {
  int number = 0;
  std::int64_t stamp_ns = 0;
  std::vector<std::string> fields;  // After the stamp.
};

// Reads "stamp field..." lines. A last line without its newline was cut off mid-write:
// it is dropped with a warning. Any other malformed line is an error naming the line.
Expected<std::vector<IndexLine>> ReadIndex(const fs::path& path, std::size_t fields_after_stamp,
                                           std::vector<std::string>* warnings) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{path.string() + ": cannot be read"};
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::vector<IndexLine> lines;
  std::size_t start = 0;
  int number = 0;
  while (start < text.size()) {
    ++number;
    const std::size_t end = text.find('\n', start);
    const bool complete = end != std::string::npos;
    const std::string line = text.substr(start, complete ? end - start : std::string::npos);
    start = complete ? end + 1 : text.size();
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    std::istringstream in_line(line);
    std::string stamp_text;
    in_line >> stamp_text;
    IndexLine parsed;
    parsed.number = number;
    const auto stamp = ParseStamp(stamp_text);
    for (std::string field; in_line >> field;) parsed.fields.push_back(field);
    const bool well_formed = stamp && parsed.fields.size() == fields_after_stamp;
    if (!complete) {
      warnings->push_back(path.string() + ": line " + std::to_string(number) +
                          " is incomplete (the recording was cut off); read " +
                          std::to_string(lines.size()) + " entries before it");
      break;
    }
    if (!well_formed) {
      return Error{path.string() + ": line " + std::to_string(number) + ": expected a timestamp and " +
                   std::to_string(fields_after_stamp) + " field(s), found '" + line + "'"};
    }
    parsed.stamp_ns = *stamp;
    lines.push_back(std::move(parsed));
  }
  return lines;
}

Expected<std::vector<double>> ParseNumbers(const fs::path& path, const IndexLine& line) {
  std::vector<double> values;
  for (const std::string& field : line.fields) {
    try {
      std::size_t used = 0;
      values.push_back(std::stod(field, &used));
      if (used != field.size()) throw std::invalid_argument(field);
    } catch (const std::exception&) {
      return Error{path.string() + ": line " + std::to_string(line.number) + ": '" + field +
                   "' is not a number"};
    }
  }
  return values;
}

RecordingMeta ParseMeta(ConfigNode& root) {
  RecordingMeta meta;
  root.Read("format_version", &meta.format_version, 1, 1);
  root.ReadChoice("source", &meta.source, {"simulator", "hardware", "tum"});
  root.Read("world", &meta.world);
  if (root.Has("seed")) {
    const YAML::Node n = root.Raw("seed");
    if (!n.IsScalar() || !YAML::convert<std::uint64_t>::decode(n, meta.seed)) {
      root.Fail("seed", "expected a non-negative integer");
    }
  }
  root.Read("duration_s", &meta.duration_s, 0.0, 1e7);
  if (root.Has("extra")) {
    const YAML::Node extra = root.Raw("extra");
    for (const auto& entry : extra) {
      meta.extra[entry.first.as<std::string>()] = entry.second.as<std::string>();
    }
  }
  return meta;
}

// A TUM RGB-D sequence has no rig: one Kinect with the default intrinsics, no latency,
// carried as a level, forward-looking camera on a "base" that is its body frame (x
// forward, y left, z up), so that maps of it are upright at the first frame.
Rig TumRig() {
  Rig rig;
  KinectMount mount;
  mount.id = "tum";
  mount.T_base_kinect = MountPose(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  mount.latency_s = 0.0;
  mount.min_range_m = 0.3;
  mount.max_range_m = 8.0;
  rig.kinects.push_back(mount);
  return rig;
}

}  // namespace

Expected<RecordingReader> RecordingReader::Open(const std::string& dir) {
  std::error_code ec;
  const fs::path root(dir);
  if (!fs::is_directory(root, ec)) return Error{dir + ": not a recording folder (does not exist)"};
  RecordingReader reader;
  reader.dir_ = dir;
  const bool has_meta = fs::exists(root / rf::kMeta, ec);
  if (has_meta) {
    auto meta = ParseYamlFile<RecordingMeta>((root / rf::kMeta).string(), ParseMeta);
    if (!meta) return meta.error();
    reader.meta_ = *meta;
    auto rig = LoadRig((root / rf::kRig).string());
    if (!rig) return rig.error();
    reader.rig_ = *rig;
  } else if (fs::exists(root / rf::DepthIndex(0), ec)) {
    reader.meta_.source = "tum";
    reader.rig_ = TumRig();
    if (fs::exists(root / rf::kRig, ec)) {
      auto rig = LoadRig((root / rf::kRig).string());
      if (!rig) return rig.error();
      reader.rig_ = *rig;
    }
  } else {
    return Error{dir + ": not a recording (neither meta.yaml nor depth.txt is there)"};
  }

  for (std::size_t s = 0; s < reader.rig_.kinects.size(); ++s) {
    const int sensor = static_cast<int>(s);
    const fs::path index = root / rf::DepthIndex(sensor);
    if (!fs::exists(index, ec)) {
      reader.warnings_.push_back(index.string() + ": missing, no frames for Kinect " +
                                 reader.rig_.kinects[s].id);
      continue;
    }
    auto lines = ReadIndex(index, 1, &reader.warnings_);
    if (!lines) return lines.error();
    for (const IndexLine& line : *lines) {
      const fs::path image = root / line.fields[0];
      if (!fs::exists(image, ec)) {
        reader.warnings_.push_back(index.string() + ": line " + std::to_string(line.number) +
                                   ": image " + line.fields[0] + " is missing, frame skipped");
        continue;
      }
      reader.depth_.push_back({sensor, line.stamp_ns, image.string()});
    }
    const fs::path label_index = root / rf::LabelIndex(sensor);
    if (fs::exists(label_index, ec)) {
      auto label_lines = ReadIndex(label_index, 1, &reader.warnings_);
      if (!label_lines) return label_lines.error();
      for (const IndexLine& line : *label_lines) {
        const std::string file = (root / line.fields[0]).string();
        reader.labels_.push_back({sensor, line.stamp_ns, file});
        reader.label_files_[{sensor, line.stamp_ns}] = file;
      }
    }
  }
  std::stable_sort(reader.depth_.begin(), reader.depth_.end(),
                   [](const DepthEntry& a, const DepthEntry& b) {
                     return a.received_ns < b.received_ns;
                   });

  if (fs::exists(root / rf::kOdometry, ec)) {
    auto lines = ReadIndex(root / rf::kOdometry, 2, &reader.warnings_);
    if (!lines) return lines.error();
    for (const IndexLine& line : *lines) {
      auto v = ParseNumbers(root / rf::kOdometry, line);
      if (!v) return v.error();
      reader.odometry_.push_back({line.stamp_ns, (*v)[0], (*v)[1]});
    }
  }
  if (fs::exists(root / rf::kImu, ec)) {
    auto lines = ReadIndex(root / rf::kImu, 3, &reader.warnings_);
    if (!lines) return lines.error();
    for (const IndexLine& line : *lines) {
      auto v = ParseNumbers(root / rf::kImu, line);
      if (!v) return v.error();
      reader.imu_.push_back({line.stamp_ns, (*v)[0], (*v)[1], (*v)[2]});
    }
  }
  if (fs::exists(root / rf::kGroundTruth, ec)) {
    auto lines = ReadIndex(root / rf::kGroundTruth, 7, &reader.warnings_);
    if (!lines) return lines.error();
    for (const IndexLine& line : *lines) {
      auto v = ParseNumbers(root / rf::kGroundTruth, line);
      if (!v) return v.error();
      const auto& x = *v;
      StampedPose pose;
      pose.stamp_ns = line.stamp_ns;
      pose.pose.linear() = Eigen::Quaterniond(x[6], x[3], x[4], x[5]).normalized().toRotationMatrix();
      pose.pose.translation() = Eigen::Vector3d(x[0], x[1], x[2]);
      reader.ground_truth_.push_back(pose);
    }
  }
  for (const std::string& warning : reader.warnings_) spdlog::warn("{}", warning);
  return reader;
}

std::int64_t RecordingReader::first_stamp_ns() const {
  std::int64_t first = std::numeric_limits<std::int64_t>::max();
  if (!odometry_.empty()) first = std::min(first, odometry_.front().stamp_ns);
  if (!imu_.empty()) first = std::min(first, imu_.front().stamp_ns);
  if (!depth_.empty()) first = std::min(first, depth_.front().received_ns);
  return first == std::numeric_limits<std::int64_t>::max() ? 0 : first;
}

std::int64_t RecordingReader::last_stamp_ns() const {
  std::int64_t last = 0;
  if (!odometry_.empty()) last = std::max(last, odometry_.back().stamp_ns);
  if (!imu_.empty()) last = std::max(last, imu_.back().stamp_ns);
  if (!depth_.empty()) last = std::max(last, depth_.back().received_ns);
  return last;
}

Status RecordingReader::UseExtrinsics(const Rig& rig, const std::string& source) {
  Rig updated = rig_;
  for (KinectMount& mount : updated.kinects) {
    const auto match = std::find_if(rig.kinects.begin(), rig.kinects.end(),
                                    [&](const KinectMount& m) { return m.id == mount.id; });
    if (match == rig.kinects.end()) {
      return Error{source + ": kinects: no Kinect with id '" + mount.id + "', which " + dir_ +
                   " recorded"};
    }
    mount.T_base_kinect = match->T_base_kinect;
    mount.latency_s = match->latency_s;
  }
  rig_ = std::move(updated);
  return Ok{};
}

Expected<DepthFrame> RecordingReader::LoadDepth(const DepthEntry& entry) const {
  auto image = ReadDepthImage(entry.file);
  if (!image) return image.error();
  const KinectMount& mount = rig_.kinects.at(static_cast<std::size_t>(entry.sensor_id));
  DepthFrame frame;
  frame.sensor_id = entry.sensor_id;
  frame.received_ns = entry.received_ns;
  frame.stamp_ns = entry.received_ns - SecondsToNanos(mount.latency_s);
  frame.width = image->width;
  frame.height = image->height;
  frame.intrinsics = mount.intrinsics;
  if (frame.width != mount.intrinsics.width || frame.height != mount.intrinsics.height) {
    return Error{entry.file + ": image is " + std::to_string(frame.width) + "x" +
                 std::to_string(frame.height) + " but the rig says " +
                 std::to_string(mount.intrinsics.width) + "x" +
                 std::to_string(mount.intrinsics.height) + " for " + mount.id};
  }
  frame.depth_mm = TumToMillimetres(image->values);
  return frame;
}

std::optional<LabelFrame> RecordingReader::LoadLabels(const DepthEntry& depth_entry) const {
  const auto it = label_files_.find({depth_entry.sensor_id, depth_entry.received_ns});
  if (it == label_files_.end()) return std::nullopt;
  auto image = ReadDepthImage(it->second);
  if (!image) return std::nullopt;
  const KinectMount& mount = rig_.kinects.at(static_cast<std::size_t>(depth_entry.sensor_id));
  LabelFrame labels;
  labels.sensor_id = depth_entry.sensor_id;
  labels.stamp_ns = depth_entry.received_ns - SecondsToNanos(mount.latency_s);
  labels.width = image->width;
  labels.height = image->height;
  labels.labels = std::move(image->values);
  return labels;
}

Expected<DepthFrame> ReadTumDepthPng(const std::string& file) {
  auto image = ReadDepthImage(file);
  if (!image) return image.error();
  DepthFrame frame;
  frame.width = image->width;
  frame.height = image->height;
  frame.intrinsics = Intrinsics{}.Scaled(frame.width, frame.height);
  frame.depth_mm = TumToMillimetres(image->values);
  return frame;
}

}  // namespace dynamap::robotio
