#include "dynamap/robotio/ConfigReader.hpp"

#include <gtest/gtest.h>

#include <fstream>

#include "TestPaths.hpp"

namespace dynamap::robotio {
namespace {

struct Example {
  double speed = 0.5;
  int count = 3;
  std::string mode = "fast";
  double nested_value = 1.0;
};

Example ParseExample(ConfigNode& root) {
  Example e;
  root.Read("speed", &e.speed, 0.0, 2.0);
  root.Read("count", &e.count, 1, 10);
  root.ReadChoice("mode", &e.mode, {"fast", "slow"});
  if (auto child = root.OptionalChild("nested")) child->Read("value", &e.nested_value, 0.0, 5.0);
  return e;
}

Expected<Example> Parse(const std::string& text) {
  return ParseYamlText<Example>(text, "example.yaml", ParseExample);
}

TEST(ConfigReader, KeepsDefaultsForAbsentKeys) {
  auto e = Parse("speed: 1.5\n");
  ASSERT_TRUE(e.ok()) << e.error().message;
  EXPECT_DOUBLE_EQ(e->speed, 1.5);
  EXPECT_EQ(e->count, 3);
  EXPECT_EQ(e->mode, "fast");
}

TEST(ConfigReader, UnknownKeyIsAnErrorNamingFileAndKey) {
  auto e = Parse("speed: 1.0\nsped: 2.0\n");
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("example.yaml"), std::string::npos) << e.error().message;
  EXPECT_NE(e.error().message.find("'sped'"), std::string::npos) << e.error().message;
}

TEST(ConfigReader, UnknownNestedKeyIsAnErrorWithItsPath) {
  auto e = Parse("nested:\n  value: 1.0\n  valeu: 2.0\n");
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("'nested.valeu'"), std::string::npos) << e.error().message;
}

TEST(ConfigReader, WrongTypeIsAnErrorNamingKeyAndExpectation) {
  auto e = Parse("count: many\n");
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("'count'"), std::string::npos) << e.error().message;
  EXPECT_NE(e.error().message.find("integer"), std::string::npos) << e.error().message;
}

TEST(ConfigReader, OutOfRangeValueIsAnErrorNamingTheAllowedRange) {
  auto e = Parse("speed: 7.5\n");
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("'speed'"), std::string::npos) << e.error().message;
  EXPECT_NE(e.error().message.find("[0, 2]"), std::string::npos) << e.error().message;
}

TEST(ConfigReader, ChoiceOutsideTheAllowedWordsIsAnError) {
  auto e = Parse("mode: medium\n");
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("fast, slow"), std::string::npos) << e.error().message;
}

TEST(ConfigReader, MalformedYamlNamesFileAndLine) {
  auto e = Parse("speed: [1.0\ncount: 2\n");
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("example.yaml"), std::string::npos) << e.error().message;
  EXPECT_NE(e.error().message.find("line"), std::string::npos) << e.error().message;
}

TEST(ConfigReader, MissingFileIsAnErrorNamingTheFile) {
  auto e = ParseYamlFile<Example>("/nonexistent/dir/config.yaml", ParseExample);
  ASSERT_FALSE(e.ok());
  EXPECT_NE(e.error().message.find("/nonexistent/dir/config.yaml"), std::string::npos);
  EXPECT_NE(e.error().message.find("not found"), std::string::npos);
}

TEST(ConfigReader, ReadsFromFile) {
  const std::string file = test::ScratchDir() + "/c.yaml";
  std::ofstream(file) << "count: 7\nmode: slow\n";
  auto e = ParseYamlFile<Example>(file, ParseExample);
  ASSERT_TRUE(e.ok()) << e.error().message;
  EXPECT_EQ(e->count, 7);
  EXPECT_EQ(e->mode, "slow");
}

}  // namespace
}  // namespace dynamap::robotio
