#include "cli/FinalMap.hpp"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <fstream>
#include <string>
#include <utility>
#include <nlohmann/json.hpp>

#include "cli/CommandSupport.hpp"
#include "cli/MapCommand.hpp"

namespace dynamap::app {

void BuildFinalMap(const FinalMapRequest& request) {
  const std::string trajectory = request.mission_dir + "/trajectory.tum";
  const std::string out = request.mission_dir + "/final_map";
  spdlog::info("final map along the loop-closed trajectory: dynamap map --log {} "
               "--trajectory {} --out {}",
               request.recording_dir, trajectory, out);
  const nlohmann::json final_report = MapAlongTrajectory(
      {request.recording_dir, trajectory, out, request.mapping_file, request.rig_file});

  const std::string report_file = request.mission_dir + "/report.json";
  std::ifstream in(report_file);
  nlohmann::json report = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!report.is_object()) {
    FailCommand("explore",
                report_file + ": not the mission's JSON report; the final map is in " + out);
  }
  nlohmann::json figures = {{"dir", "final_map"}};
  for (const char* key : {"ate_rmse_m", "static_accuracy", "dynamic_accuracy",
                          "associated_accuracy", "static_map_precision",
                          "static_map_completeness", "static_occupied_voxels"}) {
    if (final_report.contains(key)) figures[key] = final_report[key];
  }
  report["final_map"] = figures;
  if (report.contains("files") && report["files"].is_array()) {
    report["files"].push_back("final_map");
  }
  WriteJsonReport("explore", report, report_file);

  // Accuracy only where the recording has labels, surfaces only where it has a world.
  std::string line = "final map (" + out + "):";
  char part[64];
  for (const auto& [key, name] : {std::pair{"static_accuracy", "SA"},
                                  std::pair{"dynamic_accuracy", "DA"},
                                  std::pair{"static_map_precision", "precision"},
                                  std::pair{"static_map_completeness", "completeness"}}) {
    if (!figures.contains(key) || !figures[key].is_number()) continue;
    std::snprintf(part, sizeof(part), " %s %.3f", name, figures[key].get<double>());
    line += part;
  }
  std::printf("%s\n", line.c_str());
}

}  // namespace dynamap::app
