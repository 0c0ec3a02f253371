// The mediator of the mission runtime (thesis 2.2, Figure 2.3): the one place the sensor,
// SLAM, planning and control threads exchange data. Each kind of data is a newest-value
// slot or a small locked buffer, so no worker ever waits on another's computation.
#pragma once

#include <array>
#include <atomic>
#include <memory>
#include <optional>
#include <mutex>
#include <vector>

#include "dynamap/app/runtime/FrameQueue.hpp"
#include "dynamap/app/runtime/LatestValue.hpp"
#include "dynamap/app/runtime/MissionClock.hpp"
#include "dynamap/app/runtime/OdometryHistory.hpp"
#include "dynamap/app/runtime/RunControl.hpp"
#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TargetPlanner.hpp"
#include "dynamap/planning/TraversalGrid.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::app::runtime {

inline constexpr int kMaxKinects = 4;

// SLAM's newest estimate, tied to the odometry pose at the same instant so control can
// extrapolate it to "now" with the odometry that arrived since.
struct PoseFix {
  std::int64_t stamp_ns = 0;
  robotio::Pose2D T_map_base;
  robotio::Pose2D T_odom_base;
};

// The mapping worker's newest projection of the dual map.
struct ProjectedGrid {
  planning::GridMap map;
  // Cells that are obstacles only because of the dynamic map (people walking, a door just
  // closed): the planner lets them move on instead of giving up targets behind them.
  std::vector<int> dynamic_obstacles;
};

// What the planner decided last.
struct Plan {
  std::int64_t stamp_ns = 0;
  planning::TargetKind kind = planning::TargetKind::kFrontier;
  bool has_goal = false;
  Eigen::Vector2d goal_map = Eigen::Vector2d::Zero();     // m, map frame.
  std::vector<Eigen::Vector2d> path_map;                  // Shortened waypoints, m.
  std::optional<Eigen::Vector2d> look_at_map;             // What to face at the goal, m.
  // The path keeps only the squeeze radius from the map's obstacle cells
  // (planning::FindSqueezePath): the map guard measures with it as well.
  bool squeezed = false;
  std::vector<Eigen::Vector2d> frontier_targets_map;      // Candidate viewpoints, m.
  // Frontier regions passed over (centres, m): no viewpoint reachable, or blacklisted.
  std::vector<Eigen::Vector2d> unreachable_frontiers_map;
  std::vector<Eigen::Vector2d> blacklisted_frontiers_map;
  double plan_ms = 0.0;                                   // Wall time of this plan.
  std::shared_ptr<const planning::GridMap> map;           // Grid the plan was made on.
  std::shared_ptr<const planning::TraversalGrid> traversal;  // Its inflated cost grid.
  // The same with unknown cells not counted as obstacles: what the follower reads its
  // clearance from (unknown space ahead is the guard's business, not a reason to crawl).
  std::shared_ptr<const planning::TraversalGrid> clearance;
};

// Counters the workers bump and the report and front ends read.
struct MissionCounters {
  std::atomic<std::int64_t> frames_processed{0};
  std::atomic<std::int64_t> registrations_accepted{0};
  std::atomic<std::int64_t> registrations_rejected{0};
  // Keyframes whose closures moved the pose as they were found (correct_while_running).
  std::atomic<std::int64_t> loop_closures{0};
  std::atomic<std::int64_t> collisions{0};
  std::atomic<std::int64_t> guard_stops{0};
  std::atomic<std::int64_t> map_guard_stops{0};  // Control steps the map guard held back.
  // Times the map guard held the base so long that the way ahead went to the planner.
  std::atomic<std::int64_t> map_guard_give_ups{0};
  // Control steps driven with the path shifted more than 2 cm off what was seen lately
  // (planning::PathShift), and the largest shift (mm).
  std::atomic<std::int64_t> path_shift_steps{0};
  std::atomic<std::int64_t> path_shift_max_mm{0};
  std::atomic<std::int64_t> stall_stops{0};  // Times the base was found pressed against something.
  std::atomic<std::int64_t> plans{0};
  std::atomic<std::int64_t> unreachable_targets{0};
  std::atomic<std::int64_t> blocked_plans{0};  // Plans that waited for people to move on.
  std::atomic<std::int64_t> squeezed_plans{0};  // Paths only the squeeze radius found.
  std::atomic<std::int64_t> last_try_regions{0};  // Blacklisted regions let off once more.
  // Simulated time up to which each worker has finished its work (lockstep pacing).
  std::atomic<std::int64_t> slam_done_ns{-1};
  std::atomic<std::int64_t> planning_done_ns{-1};
  std::atomic<std::int64_t> control_done_ns{-1};
  std::atomic<std::int64_t> last_frame_received_ns{-1};
  std::atomic<bool> looked_around{false};      // Control finished the first turn in place.
  std::atomic<bool> exploration_done{false};   // Planner: nothing left worth reaching.
  std::atomic<bool> returned_to_start{false};  // ... and the robot is back at the start.
};

class Mediator {
 public:
  Mediator(double speed, mapping::MotionModelConfig motion);

  RunControl control;
  MissionClock clock;
  FrameQueue frames;
  OdometryHistory odometry;
  std::array<LatestValue<robotio::DepthFrame>, kMaxKinects> latest_depth;
  LatestValue<PoseFix> pose_fix;
  LatestValue<std::shared_ptr<const ProjectedGrid>> grid;
  LatestValue<Plan> plan;
  LatestValue<robotio::VelocityCommand> command;
  // A copy of the dual map for a front end's 3D view, made by the mapping worker after its
  // next batch when one is asked for (nothing is copied when no one asks).
  std::atomic<bool> map_copy_wanted{false};
  LatestValue<std::shared_ptr<const mapping::DualOcTree>> map_copy;
  MissionCounters counters;

  // The pose estimate now: SLAM's newest fix moved on by the odometry since (T_map_base).
  [[nodiscard]] robotio::Pose2D CurrentPose() const;

  // Collision-guard obstacles (map frame) for the planner, taken once.
  void ReportObstacles(const std::vector<Eigen::Vector2d>& points_map);
  [[nodiscard]] std::vector<Eigen::Vector2d> TakeObstacles();

  // Trajectories of the run (estimated at SLAM rate; true from the simulator).
  void AddEstimate(const robotio::StampedPose& pose);
  void AddOdometryEstimate(const robotio::StampedPose& pose);  // Odometry alone, same stamps.
  void AddGroundTruth(const std::vector<robotio::StampedPose>& poses);
  [[nodiscard]] robotio::Trajectory Estimates() const;
  [[nodiscard]] robotio::Trajectory OdometryEstimates() const;
  [[nodiscard]] robotio::Trajectory GroundTruth() const;
  [[nodiscard]] std::vector<robotio::Pose2D> Trail() const;  // Estimated, decimated.
  // RMS position error of the estimates so far against the ground truth at their stamps
  // (interpolated): the ATE while the mission runs; nullopt without ground truth.
  [[nodiscard]] std::optional<double> LiveAte() const;

  // Wakes every waiting worker (stop).
  void WakeAll();

  // Lockstep (speed 0): a sensor driver about to advance to mission time `t_ns` waits until
  // control has run within `control_period_s` of it, planning within `replan_period_s`,
  // and SLAM has taken every frame delivered; false when the mission stops first.
  bool WaitForWorkers(std::int64_t t_ns, double control_period_s, double replan_period_s);

 private:
  mutable std::mutex obstacles_mutex_;
  std::vector<Eigen::Vector2d> obstacles_;
  mutable std::mutex trajectory_mutex_;
  robotio::Trajectory estimates_;
  robotio::Trajectory odometry_estimates_;
  robotio::Trajectory ground_truth_;
  double live_squared_error_ = 0.0;
  std::int64_t live_error_count_ = 0;
  std::vector<robotio::Pose2D> trail_;
};

}  // namespace dynamap::app::runtime
