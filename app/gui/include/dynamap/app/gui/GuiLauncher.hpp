// Entry point of the desktop application for `dynamap gui` and for `dynamap` with no
// subcommand: sets up Qt and VTK's OpenGL format, shows the main window, runs the loop.
#pragma once

#include <string>

namespace dynamap::app::gui {

class MainWindow;

struct GuiOptions {
  std::string map_file;       // opened in the Maps workspace at start when not empty.
  std::string explore_world;  // when not empty: the Mission workspace starts a mission in it.
  std::string explore_out;    // results folder of that mission; empty: the workspace's default.
  double explore_max_time_s = 0.0;  // simulated time limit of that mission, s; 0: the panel's.
  std::string explore_poses;        // runtime::ToString of a PoseSource; empty: the panel's.
  int explore_kinect_width = 0;     // Kinect image width, px (height 3/4 of it); 0: the panel's.
};

// What `options` asks of a shown window at start: open a map or start a mission.
void ApplyStartOptions(MainWindow& window, const GuiOptions& options);

// True when an X11 or Wayland display is there to open a window on.
[[nodiscard]] bool DisplayAvailable();

// Runs the application until its window closes; returns the process exit code. Never
// throws: errors are printed to stderr and give exit code 1.
[[nodiscard]] int RunGui(int& argc, char** argv, const GuiOptions& options);

}  // namespace dynamap::app::gui
