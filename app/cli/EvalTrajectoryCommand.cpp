#include "cli/EvalTrajectoryCommand.hpp"

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "cli/CommandSupport.hpp"
#include "dynamap/mapping/TrajectoryEvaluation.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::app {
namespace {

constexpr const char* kCommand = "eval-trajectory";

struct EvalTrajectoryOptions {
  std::string ground_truth;
  std::string estimate;
  mapping::TrajectoryEvaluationConfig config;
};

nlohmann::json StatisticsJson(const mapping::ErrorStatistics& stats) {
  return {{"rmse_m", stats.rmse}, {"mean_m", stats.mean}, {"median_m", stats.median},
          {"std_m", stats.std},   {"min_m", stats.min},   {"max_m", stats.max}};
}

void Run(const EvalTrajectoryOptions& options) {
  const auto ground_truth = robotio::ReadTumTrajectory(options.ground_truth);
  if (!ground_truth) FailCommand(kCommand, ground_truth.error().message);
  const auto estimate = robotio::ReadTumTrajectory(options.estimate);
  if (!estimate) FailCommand(kCommand, estimate.error().message);
  const auto result = mapping::EvaluateTrajectory(*ground_truth, *estimate, options.config);
  if (!result) {
    FailCommand(kCommand, "too few poses of " + options.estimate + " have a pose of " +
                              options.ground_truth + " within " +
                              std::to_string(options.config.max_stamp_difference_s) +
                              " s (need 3 with --align, 1 without)");
  }
  nlohmann::json report = {
      {"ground_truth", options.ground_truth},
      {"estimate", options.estimate},
      {"aligned", options.config.align},
      {"max_stamp_difference_s", options.config.max_stamp_difference_s},
      {"pairs", result->pairs},
      {"ate_rmse_m", result->ate_m.rmse},
      {"ate", StatisticsJson(result->ate_m)},
  };
  if (result->rpe) {
    report["rpe_segment_m"] = options.config.rpe_segment_m;
    report["rpe_segments"] = result->rpe->segments;
    report["rpe_trans_m_per_m"] = result->rpe->trans_m_per_m;
    report["rpe_rot_deg_per_m"] = result->rpe->rot_deg_per_m;
  } else {
    // The ground-truth path is shorter than one RPE segment.
    report["rpe_trans_m_per_m"] = nullptr;
    report["rpe_rot_deg_per_m"] = nullptr;
  }
  std::printf("%s\n", report.dump(2).c_str());
}

}  // namespace

void RegisterEvalTrajectoryCommand(CLI::App& app) {
  auto options = std::make_shared<EvalTrajectoryOptions>();
  CLI::App* command = app.add_subcommand(
      kCommand,
      "Absolute trajectory error (and relative pose error per metre) of a TUM trajectory "
      "against ground truth, as JSON on stdout");
  command->add_option("GROUNDTRUTH", options->ground_truth, "Ground-truth TUM trajectory file")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("ESTIMATE", options->estimate, "Estimated TUM trajectory file")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_flag("--align", options->config.align,
                    "Rigidly align the estimate to the ground truth first (no scale)");
  command->add_option("--max-difference", options->config.max_stamp_difference_s,
                      "Largest stamp difference for a pose pair, s")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  command->add_option("--rpe-segment", options->config.rpe_segment_m,
                      "Ground-truth path length of one relative-pose segment, m")
      ->check(CLI::Range(0.01, 1000.0))
      ->capture_default_str();
  command->callback([options] { Run(*options); });
}

}  // namespace dynamap::app
