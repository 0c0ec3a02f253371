// `dynamap explore`: an autonomous exploration mission in a simulated world.
#pragma once

#include <CLI/CLI.hpp>

namespace dynamap::app {

void RegisterExploreCommand(CLI::App& app);

}  // namespace dynamap::app
