#include "dynamap/planning/PlanningConfig.hpp"

namespace dynamap::planning {

namespace {

constexpr double kHuge = 1e6;

void ReadProjection(robotio::ConfigNode& n, ProjectionConfig* c) {
  n.Read("robot_height_m", &c->robot_height_m, 0.1, 3.0);
  n.Read("step_height_m", &c->step_height_m, 0.0, 0.5);
  n.Read("floor_band_m", &c->floor_band_m, 0.0, 0.5);
  n.Read("hole_depth_m", &c->hole_depth_m, 0.0, 3.0);
  n.Read("max_floor_gap_m", &c->max_floor_gap_m, 0.0, 1.0);
  n.Read("dynamic_obstacle_ttl_s", &c->dynamic_obstacle_ttl_s, 0.0, 3600.0);
}

void ReadCost(robotio::ConfigNode& n, CostFieldConfig* c) {
  n.Read("robot_radius_m", &c->robot_radius_m, 0.0, 2.0);
  n.Read("proximity_range_m", &c->proximity_range_m, 0.0, 5.0);
  n.Read("proximity_weight", &c->proximity_weight, 0.0, 100.0);
  n.Read("unknown_is_obstacle", &c->unknown_is_obstacle);
  n.Read("unknown_radius_m", &c->unknown_radius_m, 0.0, 2.0);
  n.Read("hole_margin_m", &c->hole_margin_m, 0.0, 2.0);
}

void ReadTargets(robotio::ConfigNode& n, TargetPlannerConfig* c) {
  n.ReadChoice("strategy", &c->strategy, {"gain", "tour", "nearest-frontier"});
  n.Read("min_frontier_length_m", &c->min_frontier_length_m, 0.0, 10.0);
  n.Read("sensor_range_m", &c->sensor_range_m, 0.5, 20.0);
  n.Read("viewpoint_radius_m", &c->viewpoint_radius_m, 0.0, 10.0);
  n.Read("min_view_distance_m", &c->min_view_distance_m, 0.0, 10.0);
  n.Read("min_gain_m2", &c->min_gain_m2, 0.0, kHuge);
  n.Read("path_cost_offset_m", &c->path_cost_offset_m, 0.01, kHuge);
  n.Read("inspection", &c->inspection);
  n.Read("frontiers_first", &c->frontiers_first);
  n.Read("inspection_weight", &c->inspection_weight, 0.0, kHuge);
  n.Read("min_inspection_m", &c->min_inspection_m, 0.0, kHuge);
  n.Read("home_tolerance_m", &c->home_tolerance_m, 0.0, 10.0);
  n.Read("tour_scale_m", &c->tour_scale_m, 0.01, kHuge);
  n.Read("tour_cell_m", &c->tour_cell_m, 0.01, 2.0);
  if (auto b = n.OptionalChild("blacklist")) {
    b->Read("duration_s", &c->blacklist.duration_s, 0.0, kHuge);
    b->Read("max_duration_s", &c->blacklist.max_duration_s, 0.0, kHuge);
    b->Read("radius_m", &c->blacklist.radius_m, 0.0, 10.0);
    b->Read("max_failures", &c->blacklist.max_failures, 1, 100);
    b->Read("last_try", &c->blacklist.last_try);
  }
}

void ReadFollower(robotio::ConfigNode& n, PathFollowerConfig* c) {
  n.Read("max_speed_mps", &c->max_speed_mps, 0.0, 5.0);
  n.Read("max_yaw_rate_radps", &c->max_yaw_rate_radps, 0.0, 10.0);
  n.Read("max_accel_mps2", &c->max_accel_mps2, 0.01, 10.0);
  n.Read("max_yaw_accel_radps2", &c->max_yaw_accel_radps2, 0.01, 50.0);
  n.Read("lookahead_m", &c->lookahead_m, 0.05, 5.0);
  n.Read("min_lookahead_m", &c->min_lookahead_m, 0.05, 5.0);
  n.Read("heading_gain", &c->heading_gain, 0.0, 20.0);
  n.Read("turn_in_place_rad", &c->turn_in_place_rad, 0.05, 3.2);
  n.Read("slow_clearance_m", &c->slow_clearance_m, 0.0, 5.0);
  n.Read("stop_clearance_m", &c->stop_clearance_m, 0.0, 5.0);
  n.Read("creep_speed_mps", &c->creep_speed_mps, 0.0, 1.0);
  n.Read("goal_tolerance_m", &c->goal_tolerance_m, 0.01, 5.0);
}

void ReadGuard(robotio::ConfigNode& n, CollisionGuardConfig* c) {
  n.Read("footprint_radius_m", &c->footprint_radius_m, 0.05, 2.0);
  n.Read("safety_margin_m", &c->safety_margin_m, 0.0, 1.0);
  n.Read("min_height_m", &c->min_height_m, -1.0, 1.0);
  n.Read("max_height_m", &c->max_height_m, 0.1, 3.0);
  n.Read("max_decel_mps2", &c->max_decel_mps2, 0.05, 10.0);
  n.Read("reaction_time_s", &c->reaction_time_s, 0.0, 2.0);
  n.Read("min_points", &c->min_points, 1, 100000);
  n.Read("pixel_stride", &c->pixel_stride, 1, 16);
  n.Read("backoff_speed_mps", &c->backoff_speed_mps, 0.0, 1.0);
  n.Read("turn_rate_radps", &c->turn_rate_radps, 0.0, 3.0);
  n.Read("report_range_m", &c->report_range_m, 0.0, 10.0);
}

void ReadMemory(robotio::ConfigNode& n, ObstacleMemoryConfig* c) {
  n.Read("cell_m", &c->cell_m, 0.005, 1.0);
  n.Read("keep_s", &c->keep_s, 0.0, 600.0);
  n.Read("keep_hidden_s", &c->keep_hidden_s, 0.0, 3600.0);
  n.Read("range_m", &c->range_m, 0.1, 20.0);
}

void ReadPathShift(robotio::ConfigNode& n, PathShiftConfig* c) {
  n.Read("enabled", &c->enabled);
  n.Read("max_shift_m", &c->max_shift_m, 0.0, 1.0);
  n.Read("step_m", &c->step_m, 0.005, 0.5);
  n.Read("behind_m", &c->behind_m, 0.0, 5.0);
  n.Read("ahead_m", &c->ahead_m, 0.0, 5.0);
  n.Read("sample_m", &c->sample_m, 0.01, 1.0);
  n.Read("comfort_m", &c->comfort_m, 0.0, 1.0);
  n.Read("shift_cost", &c->shift_cost, 0.0, 10.0);
  n.Read("min_gain_m", &c->min_gain_m, 0.0, 1.0);
  n.Read("rate_mps", &c->rate_mps, 0.0, 5.0);
}

}  // namespace

PlanningConfig ParsePlanningConfig(robotio::ConfigNode& node, PlanningConfig config) {
  node.ReadChoice("planner", &config.planner, {"dstar", "astar"});
  node.Read("replan_period_s", &config.replan_period_s, 0.01, 60.0);
  node.Read("temporary_obstacle_s", &config.temporary_obstacle_s, 0.0, 3600.0);
  if (auto n = node.OptionalChild("projection")) ReadProjection(*n, &config.projection);
  if (auto n = node.OptionalChild("cost")) ReadCost(*n, &config.cost);
  if (auto n = node.OptionalChild("targets")) ReadTargets(*n, &config.targets);
  if (auto n = node.OptionalChild("coverage")) {
    n->Read("inspection_distance_m", &config.coverage.inspection_distance_m, 0.1, 20.0);
    n->Read("sensor_fov_rad", &config.coverage.sensor_fov_rad, 0.1, 6.2832);
  }
  if (auto n = node.OptionalChild("follower")) ReadFollower(*n, &config.follower);
  if (auto n = node.OptionalChild("guard")) ReadGuard(*n, &config.guard);
  if (auto n = node.OptionalChild("memory")) ReadMemory(*n, &config.memory);
  if (auto n = node.OptionalChild("path_shift")) ReadPathShift(*n, &config.path_shift);
  if (config.projection.step_height_m >= config.projection.robot_height_m) {
    node.Fail("projection.step_height_m", "must be below projection.robot_height_m");
  }
  if (config.follower.stop_clearance_m >= config.follower.slow_clearance_m) {
    node.Fail("follower.stop_clearance_m", "must be below follower.slow_clearance_m");
  }
  return config;
}

robotio::Expected<PlanningConfig> LoadPlanningConfig(const std::string& file) {
  return robotio::ParseYamlFile<PlanningConfig>(
      file, [](robotio::ConfigNode& node) { return ParsePlanningConfig(node); });
}

}  // namespace dynamap::planning
