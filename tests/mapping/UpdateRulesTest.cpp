#include <gtest/gtest.h>

#include "ThesisRuleConfig.hpp"
#include "dynamap/mapping/UpdateRules.hpp"

namespace dynamap::mapping {
namespace {

class UpdateRulesTest : public ::testing::Test {
 protected:
  UpdateRules rules_ = UpdateRules::FromConfig(ThesisRuleConfig());
};

// Table 4.1, one test per row: (previous static state, observation) -> Low/High.
TEST_F(UpdateRulesTest, StaticTableRows) {
  EXPECT_EQ(StaticIncrement(StaticState::kFree, Observation::kFree, rules_), rules_.low);
  EXPECT_EQ(StaticIncrement(StaticState::kUnknown, Observation::kFree, rules_), rules_.low);
  EXPECT_EQ(StaticIncrement(StaticState::kOccupied, Observation::kFree, rules_), rules_.low);
  EXPECT_EQ(StaticIncrement(StaticState::kFree, Observation::kOccupied, rules_), rules_.low);
  EXPECT_EQ(StaticIncrement(StaticState::kUnknown, Observation::kOccupied, rules_), rules_.high);
  EXPECT_EQ(StaticIncrement(StaticState::kOccupied, Observation::kOccupied, rules_), rules_.high);
}

// Table 4.2.
TEST_F(UpdateRulesTest, DynamicTableRows) {
  EXPECT_EQ(DynamicIncrement(StaticState::kFree, Observation::kFree, rules_), rules_.low);
  EXPECT_EQ(DynamicIncrement(StaticState::kUnknown, Observation::kFree, rules_), rules_.low);
  EXPECT_EQ(DynamicIncrement(StaticState::kOccupied, Observation::kFree, rules_), rules_.low);
  EXPECT_EQ(DynamicIncrement(StaticState::kFree, Observation::kOccupied, rules_), rules_.high);
  EXPECT_EQ(DynamicIncrement(StaticState::kUnknown, Observation::kOccupied, rules_), rules_.low);
  EXPECT_EQ(DynamicIncrement(StaticState::kOccupied, Observation::kOccupied, rules_), rules_.low);
}

TEST_F(UpdateRulesTest, LowAndHighAreTheConfiguredProbabilitiesAsLogOdds) {
  MappingConfig config;
  config.prob_low = 0.3;
  config.prob_high = 0.8;
  const UpdateRules rules = UpdateRules::FromConfig(config);
  EXPECT_NEAR(rules.low, std::log(0.3 / 0.7), 1e-6);
  EXPECT_NEAR(rules.high, std::log(0.8 / 0.2), 1e-6);
}

TEST_F(UpdateRulesTest, UnknownVoxelStartsFromThePrior) {
  const DualLogOdds next =
      ApplyObservation({5.0f, 5.0f}, /*known=*/false, Observation::kOccupied, rules_);
  EXPECT_FLOAT_EQ(next.static_log_odds, rules_.high);
  EXPECT_FLOAT_EQ(next.dynamic_log_odds, rules_.low);
}

TEST_F(UpdateRulesTest, OccupiedObservationOfKnownFreeSpaceGoesToTheDynamicChannel) {
  const DualLogOdds next = ApplyObservation({-1.0f, -1.0f}, true, Observation::kOccupied, rules_);
  EXPECT_FLOAT_EQ(next.static_log_odds, -1.0f + rules_.low);
  EXPECT_FLOAT_EQ(next.dynamic_log_odds, -1.0f + rules_.high);
}

TEST_F(UpdateRulesTest, BothChannelsAreClamped) {
  const DualLogOdds up = ApplyObservation({rules_.clamp_max, rules_.clamp_min}, true,
                                          Observation::kOccupied, rules_);
  EXPECT_FLOAT_EQ(up.static_log_odds, rules_.clamp_max);
  EXPECT_FLOAT_EQ(up.dynamic_log_odds, rules_.clamp_min);
  const DualLogOdds down = ApplyObservation({rules_.clamp_min, rules_.clamp_max - 0.1f}, true,
                                            Observation::kOccupied, rules_);
  EXPECT_FLOAT_EQ(down.static_log_odds, rules_.clamp_min);  // Free + occupied = Low.
  EXPECT_FLOAT_EQ(down.dynamic_log_odds, rules_.clamp_max);
}

TEST_F(UpdateRulesTest, RegularModeIsAlgorithm2AndNeverDynamic) {
  MappingConfig config;
  config.update = UpdateMode::kRegular;
  const UpdateRules rules = UpdateRules::FromConfig(config);
  const DualLogOdds hit = ApplyObservation({-1.0f, rules.clamp_min}, true, Observation::kOccupied, rules);
  EXPECT_FLOAT_EQ(hit.static_log_odds, -1.0f + rules.high);
  EXPECT_FLOAT_EQ(hit.dynamic_log_odds, rules.clamp_min);
  const DualLogOdds fresh = ApplyObservation({}, false, Observation::kFree, rules);
  EXPECT_FLOAT_EQ(fresh.static_log_odds, rules.low);
  EXPECT_FLOAT_EQ(fresh.dynamic_log_odds, rules.clamp_min);
}

TEST(FreeThresholdTest, OneGrazingMissDoesNotBarAVoxelFromTheStaticMap) {
  // Default settings: a voxel needs more than one free observation to count as free, so a
  // floor voxel crossed once by a grazing ray and then hit is still static.
  const UpdateRules rules = UpdateRules::FromConfig(MappingConfig{});
  const DualLogOdds missed = ApplyObservation({}, false, Observation::kFree, rules);
  EXPECT_EQ(ClassifyStatic(missed.static_log_odds, rules), StaticState::kUnknown);
  const DualLogOdds hit = ApplyObservation(missed, true, Observation::kOccupied, rules);
  EXPECT_FLOAT_EQ(hit.static_log_odds, rules.low + rules.high);  // Unknown + occupied = High.
  EXPECT_EQ(ClassifyStatic(hit.static_log_odds, rules), StaticState::kOccupied);
  // Repeated free evidence still makes it free, and then a hit goes to the dynamic map.
  DualLogOdds free = missed;
  for (int i = 0; i < 3; ++i) free = ApplyObservation(free, true, Observation::kFree, rules);
  EXPECT_EQ(ClassifyStatic(free.static_log_odds, rules), StaticState::kFree);
  const DualLogOdds appeared = ApplyObservation(free, true, Observation::kOccupied, rules);
  EXPECT_GT(appeared.dynamic_log_odds, free.dynamic_log_odds);
}

// Observes a voxel of well-known free space occupied `hits` times in a row.
DualLogOdds OccupyFreeSpace(const UpdateRules& rules, int hits) {
  DualLogOdds voxel{rules.clamp_min, rules.clamp_min};
  for (int i = 0; i < hits; ++i) voxel = ApplyObservation(voxel, true, Observation::kOccupied, rules);
  return voxel;
}

TEST(PersistenceTest, ALastingChangeEntersTheStaticMapAndAShortStayDoesNot) {
  MappingConfig config;
  config.persistence_observations = 300;
  const UpdateRules rules = UpdateRules::FromConfig(config);
  const float threshold = rules.threshold;
  // Two thirds of the way (a person standing for 7 s in view): still dynamic only.
  const DualLogOdds person = OccupyFreeSpace(rules, 200);
  EXPECT_LT(person.static_log_odds, threshold);
  EXPECT_EQ(ClassifyStatic(person.static_log_odds, rules), StaticState::kFree);
  EXPECT_GE(person.dynamic_log_odds, threshold);
  // A closed door: static, and out of the dynamic map, soon after the 300 observations.
  const DualLogOdds door = OccupyFreeSpace(rules, 330);
  EXPECT_GE(door.static_log_odds, threshold);
  EXPECT_LT(door.dynamic_log_odds, threshold);
  // A free observation sets the count back: the same 330 hits with one miss in the middle
  // do not make it static.
  DualLogOdds interrupted = OccupyFreeSpace(rules, 165);
  interrupted = ApplyObservation(interrupted, true, Observation::kFree, rules);
  for (int i = 0; i < 165; ++i) {
    interrupted = ApplyObservation(interrupted, true, Observation::kOccupied, rules);
  }
  EXPECT_LT(interrupted.static_log_odds, threshold);
}

TEST(PersistenceTest, OffIsTheThesisRule) {
  MappingConfig config;
  config.persistence_observations = 0;
  const UpdateRules rules = UpdateRules::FromConfig(config);
  const DualLogOdds forever = OccupyFreeSpace(rules, 5000);
  EXPECT_FLOAT_EQ(forever.static_log_odds, rules.clamp_min);
  EXPECT_FLOAT_EQ(forever.dynamic_log_odds, rules.clamp_max);
}

TEST(MappingConfigTest, FreeThresholdAboveTheOccupancyThresholdIsRejected) {
  MappingConfig config;
  config.free_threshold = 0.6;
  const auto status = ValidateMappingConfig(config, "m.yaml");
  ASSERT_FALSE(status.ok());
  EXPECT_NE(status.error().message.find("free_threshold"), std::string::npos);
}

TEST(MappingConfigTest, ParsesYamlAndRejectsBadValuesNamingTheKey) {
  auto parse = [](const std::string& text) {
    return robotio::ParseYamlText<MappingConfig>(text, "test.yaml", [](robotio::ConfigNode& root) {
      robotio::ConfigNode node = root.Child("mapping");
      return ParseMappingConfig(node);
    });
  };
  auto ok = parse("mapping:\n  resolution_m: 0.1\n  update: regular\n  prob_low: 0.35\n");
  ASSERT_TRUE(ok) << ok.error().message;
  EXPECT_DOUBLE_EQ(ok->resolution_m, 0.1);
  EXPECT_EQ(ok->update, UpdateMode::kRegular);
  EXPECT_DOUBLE_EQ(ok->prob_low, 0.35);
  auto surface = parse("mapping:\n  surface_margin_voxels: 2\n  surface_band: false\n");
  ASSERT_TRUE(surface) << surface.error().message;
  EXPECT_DOUBLE_EQ(surface->surface_margin_voxels, 2.0);
  EXPECT_FALSE(surface->surface_band);
  EXPECT_FALSE(parse("mapping:\n  min_incidence_cos: 0\n"));
  auto persistence = parse("mapping:\n  persistence_observations: 450\n");
  ASSERT_TRUE(persistence) << persistence.error().message;
  EXPECT_EQ(persistence->persistence_observations, 450);
  EXPECT_FALSE(parse("mapping:\n  persistence_observations: -1\n"));
  auto threads = parse("mapping:\n  insert_threads: 1\n");
  ASSERT_TRUE(threads) << threads.error().message;
  EXPECT_EQ(threads->insert_threads, 1);
  EXPECT_FALSE(parse("mapping:\n  insert_threads: 0\n"));

  auto bad_range = parse("mapping:\n  prob_high: 0.4\n");
  ASSERT_FALSE(bad_range);
  EXPECT_NE(bad_range.error().message.find("test.yaml"), std::string::npos);
  EXPECT_NE(bad_range.error().message.find("prob_high"), std::string::npos);

  auto bad_choice = parse("mapping:\n  update: sometimes\n");
  ASSERT_FALSE(bad_choice);
  EXPECT_NE(bad_choice.error().message.find("update"), std::string::npos);

  auto unknown = parse("mapping:\n  resolutoin_m: 0.1\n");
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().message.find("resolutoin_m"), std::string::npos);
}

}  // namespace
}  // namespace dynamap::mapping
