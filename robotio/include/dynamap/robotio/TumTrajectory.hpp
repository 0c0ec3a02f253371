// TUM trajectory files: "timestamp tx ty tz qx qy qz qw" per line, '#' comments.
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::robotio {

struct StampedPose {
  std::int64_t stamp_ns = 0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();  // T_map_base (or the file's frame).
};

using Trajectory = std::vector<StampedPose>;

// Malformed lines are errors naming the file and line number.
[[nodiscard]] Expected<Trajectory> ReadTumTrajectory(const std::string& file);
[[nodiscard]] std::string FormatTumLine(const StampedPose& pose);
[[nodiscard]] Status WriteTumTrajectory(const Trajectory& trajectory, const std::string& file);

[[nodiscard]] StampedPose ToStampedPose(std::int64_t stamp_ns, const Pose2D& pose);

}  // namespace dynamap::robotio
