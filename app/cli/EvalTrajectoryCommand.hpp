// `dynamap eval-trajectory GROUNDTRUTH ESTIMATE [--align]`: TUM trajectory accuracy as JSON
// (DESIGN.md, Evaluation; TUM RGB-D benchmark definitions).
#pragma once

#include <CLI/CLI.hpp>

namespace dynamap::app {

void RegisterEvalTrajectoryCommand(CLI::App& app);

}  // namespace dynamap::app
