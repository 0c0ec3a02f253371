// `dynamap record --world FILE [--rig FILE] [--duration S] [--seed N] --out DIR`: runs the
// simulator along the world's scripted teleop path and writes a recording with ground
// truth (true poses, label images, the true rig), faster than real time where possible.
#pragma once

#include <CLI/CLI.hpp>

namespace dynamap::app {

void RegisterRecordCommand(CLI::App& app);

}  // namespace dynamap::app
