#include "cli/PlanGridCommand.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <numeric>
#include <string>
#include <vector>

#include "cli/CommandSupport.hpp"
#include "dynamap/planning/AStar.hpp"
#include "dynamap/planning/DStarLite.hpp"
#include "dynamap/planning/MovingAi.hpp"

namespace dynamap::app {
namespace {

constexpr const char* kCommand = "plan-grid";
constexpr double kRelativeTolerance = 1e-3;  // Scenario lengths are printed rounded.

struct PlanGridOptions {
  std::string map;
  std::string scenario;
  std::string planner = "dstar";
  std::string report;
};

double Median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const std::size_t mid = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(mid), values.end());
  const double upper = values[mid];
  if (values.size() % 2 == 1) return upper;
  return 0.5 * (upper + *std::max_element(values.begin(), values.begin() + static_cast<long>(mid)));
}

void Run(const PlanGridOptions& options) {
  const auto map = planning::LoadMovingAiMap(options.map);
  if (!map) FailCommand(kCommand, map.error().message);
  const auto problems = planning::LoadMovingAiScenario(options.scenario);
  if (!problems) FailCommand(kCommand, problems.error().message);
  const planning::TraversalGrid grid = planning::ToTraversalGrid(*map);
  for (std::size_t i = 0; i < problems->size(); ++i) {
    const auto& p = (*problems)[i];
    if (!grid.Contains(p.start) || !grid.Contains(p.goal)) {
      FailCommand(kCommand, options.scenario + ": problem " + std::to_string(i + 1) +
                                " lies outside the " + std::to_string(grid.width) + "x" +
                                std::to_string(grid.height) + " map " + options.map);
    }
  }

  std::vector<double> times_ms;
  int mismatches = 0;
  int unreachable = 0;
  long expansions = 0;
  double max_relative_error = 0.0;
  for (const auto& p : *problems) {
    const auto begin = std::chrono::steady_clock::now();
    planning::GridPath path;
    if (options.planner == "astar") {
      path = planning::AStarSearch(grid, p.start, p.goal);
    } else {
      planning::DStarLite dstar(grid, p.start, p.goal);
      path = dstar.Plan();
    }
    const auto end = std::chrono::steady_clock::now();
    times_ms.push_back(std::chrono::duration<double, std::milli>(end - begin).count());
    expansions += path.expansions;
    if (!path.found) {
      ++unreachable;
      ++mismatches;
      continue;
    }
    const double error = std::abs(path.cost - p.optimal_length) / std::max(1.0, p.optimal_length);
    max_relative_error = std::max(max_relative_error, error);
    if (error > kRelativeTolerance) ++mismatches;
  }
  const nlohmann::json report = {
      {"map", options.map},
      {"scenario", options.scenario},
      {"planner", options.planner},
      {"problems", problems->size()},
      {"mismatches", mismatches},
      {"unreachable", unreachable},
      {"relative_tolerance", kRelativeTolerance},
      {"max_relative_error", max_relative_error},
      {"median_ms", Median(times_ms)},
      {"total_ms", std::accumulate(times_ms.begin(), times_ms.end(), 0.0)},
      {"mean_expansions", problems->empty() ? 0.0
                                            : static_cast<double>(expansions) / problems->size()},
  };
  std::printf("%s\n", report.dump(2).c_str());
  if (!options.report.empty()) WriteJsonReport(kCommand, report, options.report);
}

}  // namespace

void RegisterPlanGridCommand(CLI::App& app) {
  auto options = std::make_shared<PlanGridOptions>();
  CLI::App* command = app.add_subcommand(
      kCommand,
      "Solve every problem of a Moving AI scenario (8-connected, diagonal sqrt(2), no corner "
      "cutting) and print problems, mismatches, max_relative_error and median_ms as JSON");
  command->add_option("MAP", options->map, "Moving AI .map file")->required();
  command->add_option("SCEN", options->scenario, "Moving AI .scen file for that map")
      ->required();
  command->add_option("--planner", options->planner, "Planner to run")
      ->check(CLI::IsMember({"dstar", "astar"}))
      ->capture_default_str();
  command->add_option("--report", options->report, "Also write the summary to this JSON file");
  command->callback([options] { Run(*options); });
}

}  // namespace dynamap::app
