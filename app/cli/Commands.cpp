#include "cli/Commands.hpp"

#include "cli/EvalTrajectoryCommand.hpp"
#include "cli/MapCommand.hpp"
#include "cli/PlanGridCommand.hpp"

namespace dynamap::app {

void RegisterCommands(CLI::App& app) {
  RegisterEvalTrajectoryCommand(app);
  RegisterMapCommand(app);
  RegisterPlanGridCommand(app);
}

}  // namespace dynamap::app
