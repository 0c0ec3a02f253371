// Reads world files (strict YAML, docs/WORLDS.md): every error names the file and key.
#pragma once

#include <string>

#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::robotio::sim {

[[nodiscard]] Expected<World> LoadWorld(const std::string& file);
// Same for YAML text in memory; `name` stands for the file in messages.
[[nodiscard]] Expected<World> ParseWorld(const std::string& yaml_text, const std::string& name);

}  // namespace dynamap::robotio::sim
