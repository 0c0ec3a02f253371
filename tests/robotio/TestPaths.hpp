// Paths the robotio tests read from: third-party data beside the project and a scratch
// folder per test.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace dynamap::test {

inline std::string SharedData(const std::string& relative) {
  return (std::filesystem::path(DYNAMAP_SHARED_DATA_DIR) / relative).string();
}

inline std::string Resource(const std::string& relative) {
  return (std::filesystem::path(DYNAMAP_RESOURCES_DIR) / relative).string();
}

// A fresh, empty folder under the build tree named after the running test.
inline std::string ScratchDir() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const std::filesystem::path dir = std::filesystem::path(DYNAMAP_BINARY_DIR) / "test-scratch" /
                                    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace dynamap::test
