#include "dynamap/mapping/UpdateRules.hpp"

#include <octomap/octomap_utils.h>

#include <algorithm>

namespace dynamap::mapping {

UpdateRules UpdateRules::FromConfig(const MappingConfig& config) {
  UpdateRules rules;
  rules.mode = config.update;
  rules.low = octomap::logodds(config.prob_low);
  rules.high = octomap::logodds(config.prob_high);
  rules.clamp_min = octomap::logodds(config.clamp_min);
  rules.clamp_max = octomap::logodds(config.clamp_max);
  rules.threshold = octomap::logodds(config.occupancy_threshold);
  rules.free_threshold = octomap::logodds(config.free_threshold);
  rules.surface_margin_m = static_cast<float>(config.surface_margin_voxels * config.resolution_m);
  rules.min_incidence_cos = static_cast<float>(config.min_incidence_cos);
  rules.surface_band = config.surface_band;
  rules.floor_plane = config.floor_plane;
  rules.resolution_m = static_cast<float>(config.resolution_m);
  if (config.persistence_observations > 0) {
    rules.persistence_step = (rules.free_threshold - rules.clamp_min) /
                             static_cast<float>(config.persistence_observations);
  }
  return rules;
}

float StaticIncrement(StaticState previous, Observation z, const UpdateRules& r) {
  if (z == Observation::kFree) return r.low;
  // Something appearing where free space was seen before is not static.
  return previous == StaticState::kFree ? r.low : r.high;
}

float DynamicIncrement(StaticState previous, Observation z, const UpdateRules& r) {
  if (z == Observation::kFree) return r.low;
  // Only an occupied observation of known free space is evidence of motion.
  return previous == StaticState::kFree ? r.high : r.low;
}

float StaticIncrementWithPersistence(StaticState previous, float dynamic_log_odds,
                                     Observation z, const UpdateRules& r) {
  if (r.persistence_step > 0.0f && previous == StaticState::kFree &&
      z == Observation::kOccupied && dynamic_log_odds >= r.clamp_max) {
    return r.persistence_step;
  }
  return StaticIncrement(previous, z, r);
}

StaticState ClassifyStatic(float static_log_odds, const UpdateRules& rules) {
  if (static_log_odds >= rules.threshold) return StaticState::kOccupied;
  return static_log_odds < rules.free_threshold ? StaticState::kFree : StaticState::kUnknown;
}

DualLogOdds ApplyObservation(DualLogOdds previous, bool known, Observation z,
                             const UpdateRules& rules) {
  DualLogOdds next = known ? previous : DualLogOdds{};
  if (rules.mode == UpdateMode::kRegular) {
    next.static_log_odds += z == Observation::kOccupied ? rules.high : rules.low;
    if (!known) next.dynamic_log_odds = rules.clamp_min;
  } else {
    const StaticState state =
        known ? ClassifyStatic(previous.static_log_odds, rules) : StaticState::kUnknown;
    next.static_log_odds +=
        StaticIncrementWithPersistence(state, next.dynamic_log_odds, z, rules);
    next.dynamic_log_odds += DynamicIncrement(state, z, rules);
  }
  next.static_log_odds = std::clamp(next.static_log_odds, rules.clamp_min, rules.clamp_max);
  next.dynamic_log_odds = std::clamp(next.dynamic_log_odds, rules.clamp_min, rules.clamp_max);
  return next;
}

}  // namespace dynamap::mapping
