#include "dynamap/robotio/TumTrajectory.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>

#include "dynamap/robotio/AtomicFile.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::robotio {

Expected<Trajectory> ReadTumTrajectory(const std::string& file) {
  std::ifstream in(file);
  if (!in) return Error{file + ": file not found or not readable"};
  Trajectory trajectory;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    // from_chars rather than a stringstream per line: reading dominates the run time of
    // eval-trajectory on long ground-truth files.
    const char* cursor = line.data() + first;
    const char* const end = line.data() + line.size();
    auto skip_blanks = [&] {
      while (cursor < end && (*cursor == ' ' || *cursor == '\t' || *cursor == '\r')) ++cursor;
    };
    const char* stamp_end = cursor;
    while (stamp_end < end && *stamp_end != ' ' && *stamp_end != '\t') ++stamp_end;
    const auto stamp = ParseStamp(std::string(cursor, stamp_end));
    cursor = stamp_end;
    double v[7];
    bool fields_ok = true;
    for (double& value : v) {
      skip_blanks();
      const auto [next, ec] = std::from_chars(cursor, end, value);
      fields_ok = fields_ok && ec == std::errc();
      cursor = next;
    }
    if (!fields_ok || !stamp) {
      return Error{file + ": line " + std::to_string(line_number) +
                   ": expected 'timestamp tx ty tz qx qy qz qw', found '" + line + "'"};
    }
    Eigen::Quaterniond q(v[6], v[3], v[4], v[5]);
    if (std::abs(q.norm() - 1.0) > 1e-2) {
      return Error{file + ": line " + std::to_string(line_number) +
                   ": quaternion is not of unit length"};
    }
    StampedPose pose;
    pose.stamp_ns = *stamp;
    pose.pose.linear() = q.normalized().toRotationMatrix();
    pose.pose.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
    trajectory.push_back(pose);
  }
  return trajectory;
}

std::string FormatTumLine(const StampedPose& pose) {
  const Eigen::Quaterniond q(pose.pose.linear());
  const Eigen::Vector3d t = pose.pose.translation();
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), "%s %.9f %.9f %.9f %.9f %.9f %.9f %.9f",
                FormatStamp(pose.stamp_ns).c_str(), t.x(), t.y(), t.z(), q.x(), q.y(), q.z(),
                q.w());
  return buffer;
}

Status WriteTumTrajectory(const Trajectory& trajectory, const std::string& file) {
  std::string text = "# timestamp tx ty tz qx qy qz qw\n";
  for (const StampedPose& pose : trajectory) text += FormatTumLine(pose) + "\n";
  return WriteFileAtomically(file, text);
}

StampedPose ToStampedPose(std::int64_t stamp_ns, const Pose2D& pose) {
  return {stamp_ns, pose.ToIsometry()};
}

}  // namespace dynamap::robotio
