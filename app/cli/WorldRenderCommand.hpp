// `dynamap world render FILE --out PNG`: a top-down picture of a world file.
#pragma once

#include <CLI/CLI.hpp>

namespace dynamap::app {

void RegisterWorldCommand(CLI::App& app);

}  // namespace dynamap::app
