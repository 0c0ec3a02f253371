// What every subcommand shares: failing with a clear message and a non-zero exit code,
// writing report.json atomically, and finding the bundled resources.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace dynamap::app {

// Prints "dynamap COMMAND: error: MESSAGE" to stderr and ends the command with exit code 2
// (throws CLI::RuntimeError, which main() turns into the exit code).
[[noreturn]] void FailCommand(const std::string& command, const std::string& message);

// Writes `report` (pretty-printed) to `file` atomically; fails the command on error.
void WriteJsonReport(const std::string& command, const nlohmann::json& report,
                     const std::string& file);

// Absolute path of a file under resources/ (e.g. "worlds/office.yaml").
[[nodiscard]] std::string ResourcePath(const std::string& relative);

}  // namespace dynamap::app
