#include "cli/GuiCommand.hpp"

#include <memory>
#include <utility>

#include "cli/CommandSupport.hpp"

namespace dynamap::app {

void RegisterGuiCommand(CLI::App& app, GuiLauncher launch) {
  auto options = std::make_shared<GuiCommandOptions>();
  CLI::App* gui = app.add_subcommand(
      "gui", "Open the desktop application (map inspector; needs a display)");
  gui->add_option("map", options->map_file, "Map to open at start (.ot dual map or .bt OctoMap)")
      ->check(CLI::ExistingFile);
  gui->callback([options, launch = std::move(launch)] {
    const int code = launch(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace dynamap::app
