#include "dynamap/mapping/MappingConfig.hpp"

#include <functional>
#include <sstream>

namespace dynamap::mapping {

const char* UpdateModeName(UpdateMode mode) {
  return mode == UpdateMode::kDynamic ? "dynamic" : "regular";
}

MappingConfig ParseMappingConfig(robotio::ConfigNode& node) {
  MappingConfig config;
  node.Read("resolution_m", &config.resolution_m, 0.005, 2.0);
  node.Read("max_range_m", &config.max_range_m, 0.1, 100.0);
  std::string update = UpdateModeName(config.update);
  node.ReadChoice("update", &update, {"dynamic", "regular"});
  config.update = update == "regular" ? UpdateMode::kRegular : UpdateMode::kDynamic;
  node.Read("prob_low", &config.prob_low, 0.001, 0.499);
  node.Read("prob_high", &config.prob_high, 0.501, 0.999);
  node.Read("clamp_min", &config.clamp_min, 0.001, 0.499);
  node.Read("clamp_max", &config.clamp_max, 0.501, 0.999);
  node.Read("occupancy_threshold", &config.occupancy_threshold, 0.01, 0.99);
  node.Read("free_threshold", &config.free_threshold, 0.001, 0.99);
  node.Read("surface_margin_voxels", &config.surface_margin_voxels, 0.0, 20.0);
  node.Read("min_incidence_cos", &config.min_incidence_cos, 0.01, 1.0);
  node.Read("surface_band", &config.surface_band);
  node.Read("floor_plane", &config.floor_plane);
  node.Read("edge_clearance_voxels", &config.edge_clearance_voxels, 0.0, 20.0);
  node.Read("grazing_gap_deg", &config.grazing_gap_deg, 0.0, 30.0);
  node.Read("unseen_side_depth_m", &config.unseen_side_depth_m, 0.0, 20.0);
  node.Read("persistence_observations", &config.persistence_observations, 0, 1000000);
  node.Read("voxel_filter_m", &config.voxel_filter_m, 0.005, 2.0);
  node.Read("insert_threads", &config.insert_threads, 1, 64);
  auto status = ValidateMappingConfig(config, node.file());
  if (!status) node.Fail("occupancy_threshold", status.error().message);
  return config;
}

robotio::Status ValidateMappingConfig(const MappingConfig& config, const std::string& source) {
  std::ostringstream why;
  if (!(config.resolution_m >= 0.005 && config.resolution_m <= 2.0)) {
    why << "resolution_m must lie in [0.005, 2] m, got " << config.resolution_m;
  } else if (!(config.max_range_m > 0.0)) {
    why << "max_range_m must be positive, got " << config.max_range_m;
  } else if (!(config.prob_low > 0.0 && config.prob_low < 0.5)) {
    why << "prob_low must lie in (0, 0.5), got " << config.prob_low;
  } else if (!(config.prob_high > 0.5 && config.prob_high < 1.0)) {
    why << "prob_high must lie in (0.5, 1), got " << config.prob_high;
  } else if (!(config.clamp_min > 0.0 && config.clamp_min < config.occupancy_threshold &&
               config.occupancy_threshold < config.clamp_max && config.clamp_max < 1.0)) {
    why << "need 0 < clamp_min < occupancy_threshold < clamp_max < 1, got " << config.clamp_min
        << " < " << config.occupancy_threshold << " < " << config.clamp_max;
  } else if (!(config.free_threshold > config.clamp_min &&
               config.free_threshold <= config.occupancy_threshold)) {
    why << "free_threshold must lie in (clamp_min, occupancy_threshold], got "
        << config.free_threshold;
  } else if (!(config.surface_margin_voxels >= 0.0)) {
    why << "surface_margin_voxels must not be negative, got " << config.surface_margin_voxels;
  } else if (!(config.min_incidence_cos > 0.0 && config.min_incidence_cos <= 1.0)) {
    why << "min_incidence_cos must lie in (0, 1], got " << config.min_incidence_cos;
  }
  if (why.str().empty()) return robotio::Ok{};
  return robotio::Error{source + ": mapping: " + why.str()};
}

robotio::Expected<MappingConfig> LoadMappingConfig(const std::string& file) {
  return robotio::ParseYamlFile<MappingConfig>(
      file, [](robotio::ConfigNode& root) {
        robotio::ConfigNode node = root.Child("mapping");
        return ParseMappingConfig(node);
      });
}

}  // namespace dynamap::mapping
