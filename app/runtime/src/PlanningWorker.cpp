#include "dynamap/app/runtime/PlanningWorker.hpp"

#include <spdlog/spdlog.h>

#include <chrono>
#include <cmath>
#include <utility>

#include "dynamap/planning/BlockedWay.hpp"
#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/FloorGaps.hpp"
#include "dynamap/planning/PathShortening.hpp"
#include "dynamap/planning/SqueezePath.hpp"
#include "dynamap/planning/TargetSelection.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {

PlanningWorker::PlanningWorker(Mediator& mediator, PlanningWorkerConfig config)
    : mediator_(mediator),
      config_(std::move(config)),
      targets_(config_.planning.targets, config_.resolution_m),
      coverage_(config_.planning.coverage),
      obstacles_(config_.planning.temporary_obstacle_s),
      blocked_(planning::BlockedWayConfig{config_.blocked_wait_s, 1.0}),
      dropped_([this] {
        planning::DroppedTargetConfig dropped;
        dropped.arrived_m = ArrivedM();
        dropped.same_region_m = config_.planning.targets.blacklist.radius_m;
        return dropped;
      }()),
      arrival_({ArrivedM(), config_.planning.follower.face_tolerance_rad,
                config_.face_timeout_s}) {}

double PlanningWorker::ArrivedM() const {
  return 2.0 * config_.planning.follower.goal_tolerance_m + config_.resolution_m;
}

planning::GridMap PlanningWorker::PrepareGrid(const planning::GridMap& seen,
                                              const robotio::Pose2D& pose) const {
  planning::GridMap grid = seen;
  planning::CloseFloorGaps(grid, config_.planning.projection.max_floor_gap_m);
  planning::CloseWallGaps(grid, config_.planning.projection.max_floor_gap_m);
  // As far as the path keeps from a hole: a pit's corner seen late is unknown, not floor.
  planning::ExtendHolesIntoUnknown(
      grid, config_.planning.cost.robot_radius_m + config_.planning.cost.hole_margin_m);
  planning::AssumeFloorAround(grid, 0.0, 0.0, config_.start_floor_radius_m);
  for (const robotio::Pose2D& p : mediator_.Trail()) {
    planning::AssumeFloorAround(grid, p.x, p.y, config_.known_floor_radius_m);
  }
  planning::AssumeFloorAround(grid, pose.x, pose.y, config_.known_floor_radius_m);
  return grid;
}

void PlanningWorker::PlanOnce(double now_s) {
  // Nothing is judged before the first look around: one narrow view is not a map.
  if (!mediator_.counters.looked_around.load()) return;
  const auto projected = mediator_.grid.Get();
  if (!projected || !projected->value) return;
  const auto start = std::chrono::steady_clock::now();
  const robotio::Pose2D pose = mediator_.CurrentPose();
  if (arrival_.StillFacing(projected->value->map, current_target_, pose, now_s)) return;
  // The floor assumed around visited places (too close for the Kinects to see) counts as
  // known, so frontiers lie beyond it and never at the robot's own feet.
  obstacles_.Add(mediator_.TakeObstacles(), robotio::Pose2D{}, now_s);
  obstacles_.Expire(now_s);
  const planning::GridMap seen = obstacles_.Apply(projected->value->map, now_s);
  const planning::GridMap grid = PrepareGrid(seen, pose);
  planning::TraversalGrid traversal = BuildTraversalGrid(grid, config_.planning.cost);
  const planning::GridIndex robot = grid.CellAt(pose.x, pose.y);
  const planning::GridIndex home = grid.CellAt(0.0, 0.0);
  if (!grid.Contains(robot)) return;
  planning::FreeWayOut(traversal, grid, robot, config_.planning.cost);
  // People are neither surfaces to inspect nor walls hiding what lies behind them: a
  // person's trace made inspection targets of its own (only the paths go round them).
  const std::vector<int>& dynamic_obstacles = projected->value->dynamic_obstacles;
  const planning::GridMap without_people =
      dynamic_obstacles.empty() ? grid : planning::WithoutDynamicObstacles(grid, dynamic_obstacles);
  coverage_.Observe(without_people, pose);

  // Where the full radius closes a doorway the robot fits through, the path squeezes
  // (below), so what lies beyond it is worth planning for.
  planning::TraversalGrid squeeze_grid = planning::BuildSqueezeGrid(grid, config_.planning.cost);
  planning::FreeStandingCell(squeeze_grid, robot);
  planning::TargetDecision decision =
      targets_.Plan(without_people, traversal, robot, home, &coverage_, now_s, &squeeze_grid);
  if (const int lifted = targets_.LiftBansForALastTry(decision, now_s)) {
    spdlog::debug("t {:.1f} s: nothing left but {} blacklisted regions: {} bans lifted for a "
                  "last try", now_s, decision.blacklisted_regions, lifted);
    mediator_.counters.last_try_regions += lifted;
    decision =
        targets_.Plan(without_people, traversal, robot, home, &coverage_, now_s, &squeeze_grid);
  }
  spdlog::debug("t {:.1f} s: {} regions, {} unreachable, {} blacklisted, {} candidates -> {} ({}, {})",
                now_s, decision.frontier_regions, decision.unreachable_regions,
                decision.blacklisted_regions,
                decision.candidates.size(), planning::TargetKindName(decision.kind),
                decision.cell.x, decision.cell.y);
  for (const planning::TargetCandidate& c : decision.candidates) {
    spdlog::trace("  {} region ({:.2f}, {:.2f}) from ({:.2f}, {:.2f}): gain {:.2f}, cost {:.1f} m, "
                  "tour {:.1f} m, score {:.3f}", planning::TargetKindName(c.kind),
                  grid.CenterX(c.region_center.x), grid.CenterY(c.region_center.y),
                  grid.CenterX(c.viewpoint.x), grid.CenterY(c.viewpoint.y), c.gain,
                  c.path_cost_m, c.tour_length_m, c.score);
  }
  Plan plan;
  plan.stamp_ns = robotio::SecondsToNanos(now_s);
  plan.kind = decision.kind;
  for (const auto& candidate : decision.candidates) {
    plan.frontier_targets_map.emplace_back(grid.CenterX(candidate.viewpoint.x),
                                           grid.CenterY(candidate.viewpoint.y));
  }
  for (const planning::GridIndex& c : decision.unreachable_frontiers) {
    plan.unreachable_frontiers_map.emplace_back(grid.CenterX(c.x), grid.CenterY(c.y));
  }
  for (const planning::GridIndex& c : decision.blacklisted_frontiers) {
    plan.blacklisted_frontiers_map.emplace_back(grid.CenterX(c.x), grid.CenterY(c.y));
  }
  if (decision.kind == planning::TargetKind::kDone) {
    mediator_.counters.exploration_done = true;
    mediator_.counters.returned_to_start = true;
    mediator_.plan.Set(plan);
    return;
  }
  // Keep the current target unless another is clearly better; never one at the robot's
  // feet. Such a target counts as failed only when the robot has come to look from there
  // (so an unresolvable one ends up blacklisted), never for a robot driving past it.
  const std::optional<planning::TargetCandidate> previous = current_target_;
  // Yamauchi's nearest frontier stays the plain baseline it is compared with.
  const bool keep_dropped = config_.planning.targets.strategy != "nearest-frontier";
  planning::GridIndex goal_cell = decision.cell;
  if (decision.kind != planning::TargetKind::kReturnToStart) {
    planning::TargetSelectionConfig selection_config;
    selection_config.near_m = ArrivedM();
    const planning::TargetSelection selection = planning::SelectTarget(
        decision.candidates, current_target_, grid, robot, selection_config);
    for (const auto& looked : selection.looked_from_here) {
      spdlog::debug("t {:.1f} s: looked from ({:.2f}, {:.2f}) at the {} region ({:.2f}, {:.2f}) "
                    "and it is still there: a failure", now_s, grid.CenterX(looked.viewpoint.x),
                    grid.CenterY(looked.viewpoint.y), planning::TargetKindName(looked.kind),
                    grid.CenterX(looked.region_center.x), grid.CenterY(looked.region_center.y));
      targets_.ReportFailure(looked, now_s);
    }
    if (!selection.chosen) {
      spdlog::debug("t {:.1f} s: all {} candidates at the robot's feet", now_s,
                    selection.too_near.size());
      current_target_.reset();
      mediator_.plan.Set(plan);  // Nothing to drive to this time: stand still.
      return;
    }
    current_target_ = selection.chosen;
    mediator_.counters.exploration_done = false;  // Something worth reaching again.
    if (auto kept = keep_dropped ? dropped_.Keep(previous, current_target_, decision.candidates,
                                                 grid, robot, now_s)
                                 : std::nullopt) {
      current_target_ = kept;
    }
    goal_cell = current_target_->viewpoint;
    plan.kind = current_target_->kind;
  } else {
    current_target_.reset();
    if (keep_dropped) {
      current_target_ = dropped_.Keep(previous, std::nullopt, decision.candidates, grid, robot, now_s);
    }
    if (current_target_) {
      goal_cell = current_target_->viewpoint;
      plan.kind = current_target_->kind;
    } else {
      mediator_.counters.exploration_done = true;
    }
  }
  if (!search_) {
    search_ = std::make_unique<planning::PathPlanner>(config_.planning.planner, traversal);
  } else {
    search_->SetGrid(traversal);  // D* Lite repairs only what changed.
  }
  search_->MoveStart(robot);
  if (goal_cell != goal_) {
    goal_ = goal_cell;
    goal_target_ = current_target_.value_or(decision.chosen);
    goal_since_s_ = now_s;
    search_->SetGoal(goal_);
  }
  planning::GridPath path = search_->Plan();
  const planning::TraversalGrid* path_grid = &search_->grid();  // What the path avoids.
  std::optional<planning::SqueezePath> squeeze;
  if (!path.found) {
    // Blocked only by people (or a door that has just closed): wait for a while, facing
    // the way, so that the Kinects see it clear; the target stays.
    std::optional<planning::TraversalGrid> passable;
    if (!dynamic_obstacles.empty()) {
      passable = BuildTraversalGrid(without_people, config_.planning.cost);
      planning::FreeWayOut(*passable, without_people, robot, config_.planning.cost);
    }
    const planning::BlockedWayVerdict blocked = blocked_.Judge(
        passable ? &*passable : nullptr, robot, goal_, grid.resolution_m, now_s);
    if (blocked.wait) {
      spdlog::debug("t {:.1f} s: way to ({}, {}) blocked by moving obstacles for {:.1f} s",
                    now_s, goal_.x, goal_.y, blocked.blocked_for_s);
      ++mediator_.counters.blocked_plans;
      plan.has_goal = true;  // Stand where it stands and face the way.
      plan.goal_map = {pose.x, pose.y};
      plan.path_map = {plan.goal_map};
      plan.look_at_map = Eigen::Vector2d(grid.CenterX(blocked.look_at.x),
                                         grid.CenterY(blocked.look_at.y));
    } else if ((squeeze = planning::FindSqueezePath(std::move(squeeze_grid), robot, goal_))) {
      spdlog::debug("t {:.1f} s: no path to ({}, {}) with the full radius, squeezing through "
                    "with {:.3f} m", now_s, goal_.x, goal_.y,
                    planning::SqueezeRadius(config_.planning.cost, grid.resolution_m));
      ++mediator_.counters.squeezed_plans;
      path = squeeze->path;
      path_grid = &squeeze->grid;
      plan.squeezed = true;
    } else {
      spdlog::debug("t {:.1f} s: no path from ({}, {}) to ({}, {})", now_s, robot.x, robot.y,
                    goal_.x, goal_.y);
      targets_.ReportUnreachable(goal_target_, now_s);
      ++mediator_.counters.unreachable_targets;
      goal_ = {-1, -1};
      current_target_.reset();
    }
  }
  if (path.found && now_s - goal_since_s_ > config_.target_timeout_s) {
    spdlog::debug("t {:.1f} s: the {} region ({:.2f}, {:.2f}) not reached in {:.0f} s: a failure",
                  now_s, planning::TargetKindName(goal_target_.kind),
                  grid.CenterX(goal_target_.region_center.x),
                  grid.CenterY(goal_target_.region_center.y), config_.target_timeout_s);
    targets_.ReportFailure(goal_target_, now_s);
    goal_since_s_ = now_s;
  }
  spdlog::debug("t {:.1f} s: goal ({}, {}) {}, robot ({}, {}), path {} cells", now_s, goal_.x,
                goal_.y, path.found ? "reachable" : "unreachable", robot.x, robot.y,
                path.cells.size());
  if (path.found) {
    blocked_.Clear();
    plan.has_goal = true;
    if (current_target_) {
      const planning::GridIndex look = current_target_->region_center;
      plan.look_at_map = Eigen::Vector2d(grid.CenterX(look.x), grid.CenterY(look.y));
    }
    plan.goal_map = {grid.CenterX(goal_.x), grid.CenterY(goal_.y)};
    for (const planning::GridIndex& c : planning::ShortenPath(*path_grid, path.cells)) {
      plan.path_map.emplace_back(grid.CenterX(c.x), grid.CenterY(c.y));
    }
  }
  plan.map = std::make_shared<const planning::GridMap>(grid);
  plan.traversal = std::make_shared<const planning::TraversalGrid>(std::move(traversal));
  planning::CostFieldConfig known_only = config_.planning.cost;
  known_only.unknown_is_obstacle = false;
  plan.clearance =
      std::make_shared<const planning::TraversalGrid>(BuildTraversalGrid(grid, known_only));
  plan.plan_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  plan_ms_.push_back(plan.plan_ms);
  ++mediator_.counters.plans;
  mediator_.plan.Set(std::move(plan));
}

void PlanningWorker::Run() {
  const auto period_ns = robotio::SecondsToNanos(config_.planning.replan_period_s);
  std::int64_t next_ns = 0;
  while (mediator_.control.WaitWhilePaused()) {
    if (!mediator_.clock.WaitUntil(next_ns, mediator_.control)) break;
    const std::int64_t now_ns = mediator_.clock.now_ns();
    PlanOnce(robotio::NanosToSeconds(now_ns));
    mediator_.counters.planning_done_ns = now_ns;
    next_ns = now_ns + period_ns;
  }
}

}  // namespace dynamap::app::runtime
