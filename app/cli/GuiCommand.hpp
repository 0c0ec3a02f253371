// `dynamap gui [MAP]`: opens the desktop application. The CLI stays free of Qt: the
// executable passes in the function that runs the GUI.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace dynamap::app {

struct GuiCommandOptions {
  std::string map_file;  // opened in the Maps workspace at start when not empty.
};

// Runs the GUI until its window closes and returns the exit code.
using GuiLauncher = std::function<int(const GuiCommandOptions&)>;

void RegisterGuiCommand(CLI::App& app, GuiLauncher launch);

}  // namespace dynamap::app
