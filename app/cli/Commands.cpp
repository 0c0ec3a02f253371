#include "cli/Commands.hpp"

namespace dynamap::app {

void RegisterCommands(CLI::App& app) { (void)app; }

}  // namespace dynamap::app
