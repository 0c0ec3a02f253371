// dynamap: calibrate a Kinect rig, explore autonomously, inspect and export maps.
#include <spdlog/cfg/env.h>
#include <spdlog/spdlog.h>

#include <CLI/CLI.hpp>
#include <cstdio>

#include "cli/Commands.hpp"
#include "dynamap/app/Version.hpp"

int main(int argc, char** argv) {
  spdlog::cfg::load_env_levels();  // SPDLOG_LEVEL=debug shows the workers' decisions.
  CLI::App app{"dynamap " DYNAMAP_VERSION_STRING
               ": autonomous 3D mapping of dynamic indoor scenes (Kinect rig calibration, "
               "exploration with a static and a dynamic OctoMap, map inspection and export)"};
  app.set_version_flag("--version", "dynamap " DYNAMAP_VERSION_STRING);
  app.require_subcommand(0, 1);
  dynamap::app::RegisterCommands(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  if (app.get_subcommands().empty()) {
    std::printf("%s", app.help().c_str());
    return 0;
  }
  return 0;
}
