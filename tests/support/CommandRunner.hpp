// Runs the dynamap executable from a test (DYNAMAP_EXECUTABLE) and reads what it wrote.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

namespace dynamap::test {

struct CommandResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr.
};

// `arguments` after the executable, shell-quoted by the caller; output goes to `log_file`.
inline CommandResult RunDynamap(const std::string& arguments, const std::string& log_file) {
  const std::string command =
      std::string(DYNAMAP_EXECUTABLE) + " " + arguments + " > " + log_file + " 2>&1";
  CommandResult result;
  const int status = std::system(command.c_str());
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(log_file);
  std::stringstream text;
  text << in.rdbuf();
  result.output = text.str();
  return result;
}

inline nlohmann::json ReadJson(const std::string& file) {
  std::ifstream in(file);
  return nlohmann::json::parse(in);
}

}  // namespace dynamap::test
