#include "cli/Commands.hpp"

#include "cli/CalibrateCommand.hpp"
#include "cli/EvalTrajectoryCommand.hpp"
#include "cli/ExploreCommand.hpp"
#include "cli/MapCommand.hpp"
#include "cli/PlanGridCommand.hpp"
#include "cli/RecordCommand.hpp"
#include "cli/WorldRenderCommand.hpp"

namespace dynamap::app {

void RegisterCommands(CLI::App& app) {
  RegisterCalibrateCommand(app);
  RegisterEvalTrajectoryCommand(app);
  RegisterExploreCommand(app);
  RegisterMapCommand(app);
  RegisterPlanGridCommand(app);
  RegisterRecordCommand(app);
  RegisterWorldCommand(app);
}

}  // namespace dynamap::app
