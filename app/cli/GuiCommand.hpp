// `dynamap gui [MAP]` and `dynamap gui --explore WORLD [...]`: opens the desktop application. The
// CLI stays free of Qt: the executable passes in the function that runs the GUI.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

namespace dynamap::app {

struct GuiCommandOptions {
  std::string map_file;             // opened in the Maps workspace at start when not empty.
  std::string explore_world;        // when not empty: a mission in this world starts at once.
  std::string explore_out;          // results folder of that mission; empty: the GUI's default.
  double explore_max_time_s = 0.0;  // simulated time limit of that mission, s; 0: the GUI's.
  std::string explore_poses;        // slam, odometry or groundtruth; empty: the GUI's.
  int explore_kinect_width = 0;     // simulated Kinect image width, px; 0: the GUI's.
};

// Runs the GUI until its window closes and returns the exit code.
using GuiLauncher = std::function<int(const GuiCommandOptions&)>;

// A world that cannot be loaded fails the command (exit code 2) before `launch` runs, so
// no window opens on a mission that could not start.
void RegisterGuiCommand(CLI::App& app, GuiLauncher launch);

}  // namespace dynamap::app
