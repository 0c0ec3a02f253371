// Subcommands of the `dynamap` executable. Each Register function adds one subcommand
// (with its --help) to the application; the work itself lives in the core libraries.
#pragma once

#include <CLI/CLI.hpp>

namespace dynamap::app {

// Adds every available subcommand to `app`.
void RegisterCommands(CLI::App& app);

}  // namespace dynamap::app
