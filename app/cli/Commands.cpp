#include "cli/Commands.hpp"

#include "cli/PlanGridCommand.hpp"

namespace dynamap::app {

void RegisterCommands(CLI::App& app) { RegisterPlanGridCommand(app); }

}  // namespace dynamap::app
