// `dynamap plan-grid MAP.map SCEN.scen [--planner dstar|astar]`: solves every problem of a
// Moving AI scenario and prints a JSON summary (Sturtevant 2012 benchmark; thesis 6.3).
#pragma once

#include <CLI/CLI.hpp>

namespace dynamap::app {

void RegisterPlanGridCommand(CLI::App& app);

}  // namespace dynamap::app
