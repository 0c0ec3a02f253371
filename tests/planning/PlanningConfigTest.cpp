// The planning YAML section: overrides over defaults, strict errors naming key and range.
#include <gtest/gtest.h>

#include "dynamap/planning/PlanningConfig.hpp"

namespace dynamap::planning {
namespace {

robotio::Expected<PlanningConfig> Parse(const std::string& yaml) {
  return robotio::ParseYamlText<PlanningConfig>(
      yaml, "planning.yaml", [](robotio::ConfigNode& n) { return ParsePlanningConfig(n); });
}

TEST(PlanningConfig, ReadsOverridesAndKeepsDefaults) {
  const auto config = Parse(
      "planner: astar\n"
      "targets: {strategy: nearest-frontier, blacklist: {max_failures: 3, last_try: false}}\n"
      "coverage: {inspection_distance_m: 2.0}\n"
      "guard: {footprint_radius_m: 0.4}\n"
      "memory: {keep_hidden_s: 30}\n");
  ASSERT_TRUE(config) << config.error().message;
  EXPECT_EQ(config->planner, "astar");
  EXPECT_EQ(config->targets.strategy, "nearest-frontier");
  EXPECT_EQ(config->targets.blacklist.max_failures, 3);
  EXPECT_FALSE(config->targets.blacklist.last_try);
  EXPECT_DOUBLE_EQ(config->coverage.inspection_distance_m, 2.0);
  EXPECT_DOUBLE_EQ(config->guard.footprint_radius_m, 0.4);
  EXPECT_DOUBLE_EQ(config->memory.keep_hidden_s, 30.0);
  EXPECT_DOUBLE_EQ(config->memory.keep_s, ObstacleMemoryConfig{}.keep_s);
  EXPECT_DOUBLE_EQ(config->cost.robot_radius_m, CostFieldConfig{}.robot_radius_m);
}

TEST(PlanningConfig, ReadsTheTourStrategyAndItsSettings) {
  const auto config =
      Parse("targets: {strategy: tour, tour_scale_m: 5.0, tour_cell_m: 0.15}\n");
  ASSERT_TRUE(config) << config.error().message;
  EXPECT_EQ(config->targets.strategy, "tour");
  EXPECT_DOUBLE_EQ(config->targets.tour_scale_m, 5.0);
  EXPECT_DOUBLE_EQ(config->targets.tour_cell_m, 0.15);
  const auto wrong = Parse("targets: {strategy: tsp}\n");
  ASSERT_FALSE(wrong);
  EXPECT_NE(wrong.error().message.find("targets.strategy"), std::string::npos)
      << wrong.error().message;
}

TEST(PlanningConfig, UnknownKeyIsAnErrorNamingIt) {
  const auto config = Parse("follower: {max_sped_mps: 1.0}\n");
  ASSERT_FALSE(config);
  EXPECT_NE(config.error().message.find("planning.yaml"), std::string::npos);
  EXPECT_NE(config.error().message.find("follower.max_sped_mps"), std::string::npos)
      << config.error().message;
}

TEST(PlanningConfig, OutOfRangeValueNamesKeyAndRange) {
  const auto config = Parse("cost: {robot_radius_m: 5}\n");
  ASSERT_FALSE(config);
  EXPECT_NE(config.error().message.find("cost.robot_radius_m"), std::string::npos)
      << config.error().message;
  const auto planner = Parse("planner: dijkstra\n");
  ASSERT_FALSE(planner);
  EXPECT_NE(planner.error().message.find("astar"), std::string::npos) << planner.error().message;
}

}  // namespace
}  // namespace dynamap::planning
