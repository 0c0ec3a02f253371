// dynamap: calibrate a Kinect rig, explore autonomously, inspect and export maps.
#include <spdlog/cfg/env.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/Commands.hpp"
#include "cli/GuiCommand.hpp"
#include "dynamap/app/Version.hpp"
#ifdef DYNAMAP_WITH_GUI
#include "dynamap/app/gui/GuiLauncher.hpp"
#endif

namespace {
constexpr int kBadInput = 2;
}  // namespace

int main(int argc, char** argv) {
  spdlog::cfg::load_env_levels();  // SPDLOG_LEVEL=debug shows the workers' decisions.
  CLI::App app{"dynamap " DYNAMAP_VERSION_STRING
               ": autonomous 3D mapping of dynamic indoor scenes (Kinect rig calibration, "
               "exploration with a static and a dynamic OctoMap, map inspection and export)"};
  app.set_version_flag("--version", "dynamap " DYNAMAP_VERSION_STRING);
  app.require_subcommand(0, 1);
  dynamap::app::RegisterCommands(app);
  const dynamap::app::GuiLauncher launch_gui =
      [&argc, argv](const dynamap::app::GuiCommandOptions& options) {
#ifdef DYNAMAP_WITH_GUI
        return dynamap::app::gui::RunGui(
            argc, argv,
            {options.map_file, options.explore_world, options.explore_out,
             options.explore_max_time_s, options.explore_poses, options.explore_kinect_width});
#else
        (void)options;
        (void)argv;
        std::fprintf(stderr, "dynamap gui: error: this build has no desktop application "
                             "(configured with DYNAMAP_BUILD_GUI=OFF)\n");
        return 2;
#endif
      };
  dynamap::app::RegisterGuiCommand(app, launch_gui);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return app.exit(e);  // A command failed; it has said why and chosen the code.
  } catch (const CLI::ParseError& e) {
    // Help and version end with 0; a bad command line (missing file, value out of range,
    // unknown option) with the same code as every other bad input.
    return app.exit(e) == 0 ? 0 : kBadInput;
  }
  if (app.get_subcommands().empty()) {
#ifdef DYNAMAP_WITH_GUI
    if (dynamap::app::gui::DisplayAvailable()) return launch_gui({});
#endif
    std::printf("%s", app.help().c_str());
    return 0;
  }
  return 0;
}
