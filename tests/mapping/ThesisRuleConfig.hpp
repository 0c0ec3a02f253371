// The mapping settings of the thesis's own rule: one free observation makes a voxel
// "free" for Tables 4.1/4.2 (free_threshold = occupancy threshold), which the table tests
// exercise row by row, and no lasting-change rule (persistence_observations = 0).
#pragma once

#include "dynamap/mapping/MappingConfig.hpp"

namespace dynamap::mapping {

inline MappingConfig ThesisRuleConfig() {
  MappingConfig config;
  config.free_threshold = config.occupancy_threshold;
  config.persistence_observations = 0;
  return config;
}

}  // namespace dynamap::mapping
