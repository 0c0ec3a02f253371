// The files a mission leaves behind besides the 3D maps: the projected map as a picture
// with the path taken and the last targets (map2d.png), as a ROS map_server map
// (map2d.pgm + map2d.yaml), where surfaces were seen closely (coverage.png), where the
// static map's accuracy was lost (accuracy.png), and report.json.
#pragma once

#include <string>
#include <vector>

#include "dynamap/app/runtime/MissionEvaluation.hpp"
#include "dynamap/app/runtime/MissionSnapshot.hpp"
#include "dynamap/mapping/MapEvaluation.hpp"
#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::app::runtime {

// What the planner had on the map when the mission ended (m, map frame).
struct PlannerMarks {
  std::vector<Eigen::Vector2d> targets;                // Candidate viewpoints.
  std::vector<Eigen::Vector2d> unreachable_frontiers;  // Regions no viewpoint reaches.
  std::vector<Eigen::Vector2d> blacklisted_frontiers;  // Regions given up after failed tries.
};

// Navigable white, obstacles black, holes blue, unknown grey; the true path green (when
// known), the estimated path orange, the start circled red; target candidates magenta
// diamonds, frontier regions passed over as crosses (unreachable red, blacklisted dark
// blue); 2 px per cell, north up.
[[nodiscard]] robotio::Status WriteMapPicture(const planning::GridMap& grid,
                                              const std::vector<robotio::Pose2D>& estimated,
                                              const std::vector<robotio::Pose2D>& truth,
                                              const PlannerMarks& marks, const std::string& file);

// Where the surfaces were seen closely (surface_coverage): the projected map faded, and
// each cell holding visible surface samples coloured by the share inspected, green all,
// red none; 2 px per cell, north up.
[[nodiscard]] robotio::Status WriteCoveragePicture(const planning::GridMap& grid,
                                                   const SurfaceCoverageResult& coverage,
                                                   const std::string& file);

// Where the static map's accuracy was lost (static_accuracy, dynamic_accuracy): the
// projected map faded, and each cell holding labelled static points whose voxel the final
// static map does not keep drawn blue, holding dynamic points it keeps red (purple both),
// stronger the more points (logarithmic, full in the worst cell of each colour); 2 px per
// cell, north up.
[[nodiscard]] robotio::Status WriteAccuracyPicture(const planning::GridMap& grid,
                                                   const mapping::MisclassifiedVoxels& misclassified,
                                                   const mapping::PointAccuracy& accuracy,
                                                   const std::string& file);

// map_server format: PGM (free 254, occupied 0, unknown 205) and its YAML description.
[[nodiscard]] robotio::Status WriteRosMap(const planning::GridMap& grid, const std::string& pgm,
                                          const std::string& yaml);

[[nodiscard]] robotio::Status WriteReportJson(const MissionReport& report,
                                              const std::string& extra_json_fields,
                                              const std::string& file);

}  // namespace dynamap::app::runtime
