// What a front end shows of a running mission, copied out of the mediator: pose, trail,
// projected grid, targets and path, counters; and the scored report at the end.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/app/runtime/CpuTime.hpp"
#include "dynamap/app/runtime/RunControl.hpp"
#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TargetPlanner.hpp"
#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"

namespace dynamap::app::runtime {

struct MissionSnapshot {
  MissionState state = MissionState::kIdle;
  double sim_time_s = 0.0;
  robotio::Pose2D pose;                     // Estimated T_map_base now.
  std::vector<robotio::Pose2D> trail;       // Estimated path so far.
  std::shared_ptr<const planning::GridMap> grid;  // Projected map (may be null early).
  planning::TargetKind target_kind = planning::TargetKind::kFrontier;
  bool has_goal = false;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();
  std::vector<Eigen::Vector2d> path;
  std::vector<Eigen::Vector2d> candidates;
  // Frontier regions the planner passed over (centres, m): no viewpoint it can reach, or
  // blacklisted after failed tries. What a finished exploration leaves unexplored.
  std::vector<Eigen::Vector2d> unreachable_frontiers;
  std::vector<Eigen::Vector2d> blacklisted_frontiers;
  std::vector<robotio::DepthFrame> depth;   // Newest frame per Kinect.
  double distance_m = 0.0;                  // Odometry distance driven.
  std::int64_t frames_delivered = 0;
  std::int64_t frames_dropped = 0;
  std::int64_t frames_processed = 0;
  std::int64_t collisions = 0;
  std::int64_t guard_stops = 0;
  std::int64_t loop_closures = 0;           // Times closures moved the SLAM pose.
  robotio::VelocityCommand command;         // Last velocity command sent.
  bool exploration_done = false;
  double time_limit_s = 0.0;                // Mission time at which it ends (a replay: its length).
  // With the simulator's truth (simulated worlds, simulated recordings): the ATE of the
  // estimates so far, and the known share of the floor that will be reachable at the end.
  std::optional<double> ate_so_far_m;
  std::optional<double> explored_free_fraction;
};

struct MissionReport {
  bool completed = false;               // Planner judged exploration done, robot back home.
  double explored_free_fraction = 0.0;
  double surface_coverage = 0.0;
  double path_length_m = 0.0;           // True path driven.
  double mission_time_s = 0.0;
  std::int64_t collisions = 0;
  double ate_rmse_m = 0.0;         // trajectory.tum: with every loop closure applied.
  double online_ate_rmse_m = 0.0;  // The poses as the mission had them (trajectory_online.tum).
  double odometry_ate_rmse_m = 0.0;
  double static_accuracy = 0.0;
  double dynamic_accuracy = 0.0;
  double associated_accuracy = 0.0;
  double dynamic_accuracy_above_floor = 0.0;  // mapping::PointAccuracy: feet left out.
  double static_accuracy_above_floor = 0.0;   // ... SA without the floor layer's points.
  std::int64_t frames_delivered = 0;
  std::int64_t frames_dropped = 0;
  std::int64_t frames_processed = 0;
  std::int64_t registrations_accepted = 0;
  std::int64_t registrations_rejected = 0;
  std::int64_t loop_closures = 0;  // Revisits closed and kept in the pose graph.
  std::int64_t guard_stops = 0;
  std::int64_t map_guard_stops = 0;  // Control steps the map guard held the base.
  std::int64_t map_guard_give_ups = 0;  // Holds long enough to report the way blocked.
  std::int64_t stall_stops = 0;      // Times the base stalled against something unseen.
  double path_shifted_s = 0.0;       // s driven with the path shifted > 2 cm (PathShift).
  double path_shift_max_m = 0.0;     // m, the largest path shift.
  std::int64_t plans = 0;
  std::int64_t unreachable_targets = 0;  // Goals given up: no path, even without people.
  std::int64_t blocked_plans = 0;        // Plans that stood waiting for people to move on.
  std::int64_t squeezed_plans = 0;       // Paths found only with the squeeze radius.
  std::int64_t last_try_regions = 0;     // Blacklisted regions let off for a last try.
  // The last plan's frontier regions passed over (centres, m, map frame): what the
  // exploration left unexplored when it ended.
  std::vector<Eigen::Vector2d> unreachable_frontiers;
  std::vector<Eigen::Vector2d> blacklisted_frontiers;
  double plan_median_ms = 0.0;
  double plan_p95_ms = 0.0;
  double insert_median_ms = 0.0;
  double insert_p95_ms = 0.0;
  double wall_time_s = 0.0;
  MissionCpu cpu;                       // Per-thread CPU seconds while the mission ran.
  std::vector<std::string> files;       // Written into the output folder.
};

}  // namespace dynamap::app::runtime
