// Reads world files (strict YAML, docs/WORLDS.md): every error names the file and key.
#pragma once

#include <string>
#include <vector>

#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::robotio::sim {

[[nodiscard]] Expected<World> LoadWorld(const std::string& file);
// A scripted drive on its own (`dynamap record --teleop`): a YAML file with `teleop:` (the
// world files' list of {v, omega, duration_s}) and optional `name`, `description`.
[[nodiscard]] Expected<std::vector<TeleopSegment>> LoadTeleop(const std::string& file);
// Same for YAML text in memory; `name` stands for the file in messages.
[[nodiscard]] Expected<World> ParseWorld(const std::string& yaml_text, const std::string& name);

}  // namespace dynamap::robotio::sim
