#include "cli/GuiCommand.hpp"

#include <memory>
#include <utility>

#include "cli/CommandSupport.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app {

void RegisterGuiCommand(CLI::App& app, GuiLauncher launch) {
  auto options = std::make_shared<GuiCommandOptions>();
  CLI::App* gui = app.add_subcommand(
      "gui",
      "Open the desktop application (map inspector, missions, calibration; needs a "
      "display)");
  CLI::Option* map = gui->add_option("map", options->map_file,
                                     "Map to open at start (.ot dual map or .bt OctoMap)")
                         ->check(CLI::ExistingFile);
  // Not CLI::ExistingFile: a missing world fails like the other commands' worlds do
  // (the loader's message naming the file, exit code 2).
  CLI::Option* explore =
      gui->add_option("--explore", options->explore_world,
                      "World file (YAML): open the Mission workspace on it and start an "
                      "autonomous exploration at once, as if Start had been pressed")
          ->excludes(map);
  gui->add_option("--out", options->explore_out,
                  "Results folder of the --explore mission (default: a new folder in "
                  "~/dynamap-missions)")
      ->needs(explore);
  gui->add_option("--max-time", options->explore_max_time_s,
                  "Simulated time limit of the --explore mission, s (default: the Mission "
                  "workspace's, 600)")
      ->check(CLI::Range(1.0, 7200.0))
      ->needs(explore);
  // Same names, choices and ranges as `dynamap explore`, so a mission reads the same in both.
  gui->add_option("--poses", options->explore_poses,
                  "Where the --explore mission places frames from (default: the Mission "
                  "workspace's, slam)")
      ->check(CLI::IsMember({"slam", "odometry", "groundtruth"}))
      ->needs(explore);
  gui->add_option("--kinect-width", options->explore_kinect_width,
                  "Simulated Kinect image width of the --explore mission in px (height = 3/4 "
                  "of it; default: the Mission workspace's, 320)")
      ->check(CLI::Range(80, 640))
      ->needs(explore);
  gui->callback([options, launch = std::move(launch)] {
    if (!options->explore_world.empty()) {
      if (auto world = robotio::sim::LoadWorld(options->explore_world); !world) {
        FailCommand("gui", world.error().message);
      }
    }
    const int code = launch(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace dynamap::app
