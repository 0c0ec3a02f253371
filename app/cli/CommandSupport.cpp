#include "cli/CommandSupport.hpp"

#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>

#include "dynamap/robotio/AtomicFile.hpp"

namespace dynamap::app {

void FailCommand(const std::string& command, const std::string& message) {
  std::fprintf(stderr, "dynamap %s: error: %s\n", command.c_str(), message.c_str());
  throw CLI::RuntimeError(2);
}

void WriteJsonReport(const std::string& command, const nlohmann::json& report,
                     const std::string& file) {
  auto status = robotio::WriteFileAtomically(file, report.dump(2) + "\n");
  if (!status) FailCommand(command, status.error().message);
}

std::string ResourcePath(const std::string& relative) {
  // dynamap runs from its build tree (scripts/demo), so resources come from the source tree.
  const std::filesystem::path source = std::filesystem::path(DYNAMAP_RESOURCES_DIR) / relative;
  return source.string();
}

}  // namespace dynamap::app
