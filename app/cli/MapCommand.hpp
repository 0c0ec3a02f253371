// `dynamap map`: integrates a recording into the dual static/dynamic map from known poses
// and writes the map files and report.json (thesis 4.2, 5.4; DESIGN.md Evaluation).
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::app {

void RegisterMapCommand(CLI::App& app);

struct TrajectoryMapRequest {
  std::string recording_dir;
  std::string trajectory_file;  // TUM, T_map_base.
  std::string out_dir;
  std::string mapping_file;  // "" = the default map settings.
  std::string rig_file;      // "" = the recorded rig.
};

// What `dynamap map --log R --trajectory T --out O [--mapping M] [--rig G]` does: the map
// files and report.json in `out_dir`; returns the report. Fails as that command does.
nlohmann::json MapAlongTrajectory(const TrajectoryMapRequest& request);

// Dead reckoning from the cumulative wheel distances alone (thesis 5.2.1, eq. 5.3, midpoint
// heading per interval): T_map_base at every reading, identity at the first one.
[[nodiscard]] robotio::Trajectory IntegrateWheelOdometry(
    const std::vector<robotio::OdometryReading>& odometry, double track_width_m);

// T_map_base at `stamp_ns`, interpolated in the plane between the neighbouring entries and
// clamped to the ends. `trajectory` sorted by stamp and not empty.
[[nodiscard]] Eigen::Isometry3d PoseAtStamp(const robotio::Trajectory& trajectory,
                                            std::int64_t stamp_ns);

}  // namespace dynamap::app
