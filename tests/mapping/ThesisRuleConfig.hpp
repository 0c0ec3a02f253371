// The mapping settings of the thesis's own rule: one free observation makes a voxel
// "free" for Tables 4.1/4.2 (free_threshold = occupancy threshold), which the table tests
// exercise row by row.
#pragma once

#include "dynamap/mapping/MappingConfig.hpp"

namespace dynamap::mapping {

inline MappingConfig ThesisRuleConfig() {
  MappingConfig config;
  config.free_threshold = config.occupancy_threshold;
  return config;
}

}  // namespace dynamap::mapping
