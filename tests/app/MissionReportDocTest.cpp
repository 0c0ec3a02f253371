// docs/MISSION_REPORT.md explains every field a mission's report.json carries: a field
// added to the report without a line there fails here.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <sstream>
#include <string>

#include "../robotio/TestPaths.hpp"
#include "dynamap/app/runtime/MissionOutputs.hpp"

namespace dynamap::app::runtime {
namespace {

std::string ReadText(const std::string& file) {
  std::ifstream in(file);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(MissionReportDoc, EveryReportFieldIsExplained) {
  const std::string doc = ReadText(test::Resource("../docs/MISSION_REPORT.md"));
  ASSERT_FALSE(doc.empty()) << "docs/MISSION_REPORT.md not found";
  const std::string file = test::ScratchDir() + "/report.json";
  ASSERT_TRUE(WriteReportJson(MissionReport{}, "", file));
  const nlohmann::json report = nlohmann::json::parse(ReadText(file));
  ASSERT_GT(report.size(), 30u);
  for (const auto& [key, value] : report.items()) {
    EXPECT_NE(doc.find("`" + key + "`"), std::string::npos) << key << " is not in the doc";
    if (!value.is_object()) continue;
    for (const auto& [inner, unused] : value.items()) {
      EXPECT_NE(doc.find("`" + inner + "`"), std::string::npos)
          << key << "." << inner << " is not in the doc";
    }
  }
}

}  // namespace
}  // namespace dynamap::app::runtime
