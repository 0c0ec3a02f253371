// The inverse sensor models of the dual map (thesis 4.2, Tables 4.1 and 4.2, eq. 4.11/4.12)
// and of the regular occupancy update (Algorithm 2), as pure log-odds functions.
#pragma once

#include "dynamap/mapping/MappingConfig.hpp"

namespace dynamap::mapping {

// State of a voxel in the static map before this scan. Unknown = never observed.
enum class StaticState { kFree, kUnknown, kOccupied };

// A voxel both hit and traversed within one scan counts as hit.
enum class Observation { kFree, kOccupied };

// Log-odds form of a MappingConfig, computed once.
struct UpdateRules {
  UpdateMode mode = UpdateMode::kDynamic;
  float low = 0.0f;        // log-odds of prob_low (negative).
  float high = 0.0f;       // log-odds of prob_high (positive).
  float clamp_min = 0.0f;  // log-odds.
  float clamp_max = 0.0f;  // log-odds.
  float threshold = 0.0f;  // log-odds of occupancy_threshold.
  float free_threshold = 0.0f;  // log-odds of free_threshold (below: free; between: unknown).
  float surface_margin_m = 0.0f;  // m, surface_margin_voxels * resolution_m.
  float min_incidence_cos = 1.0f;
  bool surface_band = false;
  bool floor_plane = false;      // MappingConfig::floor_plane.
  float resolution_m = 0.05f;    // m, voxel edge (the floor layers' thickness).
  // Static increment of an occupied observation of a free voxel whose dynamic channel is
  // at clamp_max (MappingConfig::persistence_observations); 0 = Table 4.1's Low.
  float persistence_step = 0.0f;

  [[nodiscard]] static UpdateRules FromConfig(const MappingConfig& config);
};

// Log-odds pair of one voxel: the static and the dynamic channel.
struct DualLogOdds {
  float static_log_odds = 0.0f;
  float dynamic_log_odds = 0.0f;
};

// Table 4.1 (static) and 4.2 (dynamic) entries as log-odds increments (eq. 4.11/4.12
// with the prior 0.5, whose log-odds is 0).
[[nodiscard]] float StaticIncrement(StaticState previous, Observation z, const UpdateRules& r);
[[nodiscard]] float DynamicIncrement(StaticState previous, Observation z, const UpdateRules& r);

// Classifies a known voxel's static log-odds; too little evidence either way is unknown.
[[nodiscard]] StaticState ClassifyStatic(float static_log_odds, const UpdateRules& rules);

// Table 4.1's increment, except for a lasting change: an occupied observation of free
// space that the dynamic channel has held occupied (at clamp_max) raises the static
// channel by persistence_step instead of lowering it.
[[nodiscard]] float StaticIncrementWithPersistence(StaticState previous, float dynamic_log_odds,
                                                   Observation z, const UpdateRules& r);

// The new values of a voxel after one observation. `known` is false for a voxel never
// observed before (its values are then ignored and start from the prior). In regular
// mode the static channel follows Algorithm 2 and the dynamic channel stays free.
[[nodiscard]] DualLogOdds ApplyObservation(DualLogOdds previous, bool known, Observation z,
                                           const UpdateRules& rules);

}  // namespace dynamap::mapping
