#include "cli/Commands.hpp"

#include "cli/MapCommand.hpp"
#include "cli/PlanGridCommand.hpp"

namespace dynamap::app {

void RegisterCommands(CLI::App& app) {
  RegisterMapCommand(app);
  RegisterPlanGridCommand(app);
}

}  // namespace dynamap::app
