#include "dynamap/app/runtime/ControlWorker.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamap/planning/CostField.hpp"
#include "dynamap/planning/MapGuard.hpp"
#include "dynamap/planning/SqueezePath.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {

ControlWorker::ControlWorker(Mediator& mediator, robotio::Rig rig, ControlWorkerConfig config)
    : mediator_(mediator),
      rig_(std::move(rig)),
      config_(config),
      follower_(config.follower),
      stall_(config.stall),
      memory_(config.memory),
      view_(rig_, config.guard.min_height_m, config.guard.max_height_m),
      shift_(config.path_shift) {}

void ControlWorker::TakeNewFrames(std::int64_t now_ns) {
  // The guard's protected zone reaches radius + stopping distance at top speed; the memory
  // keeps what is within its range.
  const double range = std::max({config_.memory.range_m, config_.guard.report_range_m,
                                 config_.guard.footprint_radius_m +
                                     config_.guard.safety_margin_m +
                                     planning::StoppingDistance(config_.follower.max_speed_mps,
                                                                config_.guard)});
  for (std::size_t i = 0; i < mediator_.latest_depth.size(); ++i) {
    if (mediator_.latest_depth[i].version() == frame_version_[i]) continue;
    const auto frame = mediator_.latest_depth[i].Get();
    if (!frame) continue;
    frame_version_[i] = frame->version;
    frame_points_[i] = planning::RobotHeightPoints(frame->value, rig_, config_.guard, range);
    // Placed by dead reckoning at the frame's capture instant (only the shift reads it).
    if (!config_.path_shift.enabled) continue;
    if (const auto odom = mediator_.odometry.PoseAt(frame->value.stamp_ns)) {
      memory_.Insert(frame_points_[i], *odom, frame->value.stamp_ns);
    }
  }
  // A point the Kinects cannot see from where the base is now (beside it, behind it, too
  // near) is not forgotten for going unseen. Without odometry nothing was remembered.
  if (const auto odom = mediator_.odometry.Latest()) {
    memory_.Forget(now_ns, odom->pose, [this](const Eigen::Vector2d& p) { return view_.Sees(p); });
  }
}

robotio::Pose2D ControlWorker::PoseOnPath(const Plan* plan, const robotio::Pose2D& pose,
                                          double dt_s) {
  if (!config_.path_shift.enabled) return pose;
  std::vector<Eigen::Vector2d> seen_map;
  const auto odom = mediator_.odometry.Latest();
  if (plan != nullptr && plan->has_goal && odom) {
    const double radius = config_.path_shift.ahead_m + config_.path_shift.max_shift_m +
                          config_.guard.footprint_radius_m + config_.path_shift.comfort_m;
    for (const Eigen::Vector2d& p : memory_.PointsNear(odom->pose, radius)) {
      const robotio::Pose2D q = pose.Compose({p.x(), p.y(), 0.0});
      seen_map.emplace_back(q.x, q.y);
    }
    // No Kinect sees a hole's edge near the base: the map's hole cells keep the shift from
    // moving the path towards one.
    if (plan->map) {
      const planning::GridMap& map = *plan->map;
      const planning::GridIndex c = map.CellAt(pose.x, pose.y);
      const int r = static_cast<int>(std::ceil(radius / map.resolution_m));
      for (int y = c.y - r; y <= c.y + r; ++y) {
        for (int x = c.x - r; x <= c.x + r; ++x) {
          const planning::GridIndex n{x, y};
          if (map.Contains(n) && map.At(n) == planning::CellState::kHole) {
            seen_map.emplace_back(map.CenterX(x), map.CenterY(y));
          }
        }
      }
    }
  }
  const Eigen::Vector2d shift =
      shift_.Update(plan != nullptr ? plan->path_map : std::vector<Eigen::Vector2d>{},
                    {pose.x, pose.y}, seen_map, config_.guard.footprint_radius_m, dt_s);
  const auto shift_mm = static_cast<std::int64_t>(std::lround(1e3 * shift.norm()));
  if (shift_mm > 20) ++mediator_.counters.path_shift_steps;
  if (shift_mm > mediator_.counters.path_shift_max_mm.load()) {
    mediator_.counters.path_shift_max_mm.store(shift_mm);
  }
  return {pose.x - shift.x(), pose.y - shift.y(), pose.theta};
}

robotio::VelocityCommand ControlWorker::Step(std::int64_t now_ns, double dt_s) {
  // Guard first, on raw frames: a person stepping in is seen before any map knows.
  TakeNewFrames(now_ns);
  std::vector<Eigen::Vector2d> points;
  for (const auto& some : frame_points_) points.insert(points.end(), some.begin(), some.end());
  const robotio::Pose2D pose = mediator_.CurrentPose();
  // Driving commanded and not moving: pressed against something no Kinect sees (within
  // their 0.5 m blind range). The planner gets it in the way; the base backs away from it.
  if (stall_.Update(pose, last_.v, dt_s)) {
    ++mediator_.counters.stall_stops;
    spdlog::debug("t {:.2f} s: the base stalled at ({:.2f}, {:.2f}) driving at {:.2f} m/s: "
                  "backing away", robotio::NanosToSeconds(now_ns), pose.x, pose.y, last_.v);
    const double direction = last_.v < 0.0 ? -1.0 : 1.0;
    mediator_.ReportObstacles(
        planning::StallObstacle(pose, config_.guard.footprint_radius_m, direction));
    recovery_ = {now_ns, -direction * config_.guard.backoff_speed_mps, 0.0};
    recovery_until_ns_ = now_ns + robotio::SecondsToNanos(config_.stall_backoff_s);
    follower_.Stop();
    return {now_ns, 0.0, 0.0};
  }
  const planning::GuardVerdict verdict =
      planning::CheckCollisionPoints(points, last_, config_.guard);
  if (verdict.stop) {
    ++mediator_.counters.guard_stops;
    std::vector<Eigen::Vector2d> obstacles_map;
    for (const Eigen::Vector2d& p : verdict.obstacle_base) {
      const robotio::Pose2D q = pose.Compose({p.x(), p.y(), 0.0});
      obstacles_map.emplace_back(q.x, q.y);
    }
    mediator_.ReportObstacles(obstacles_map);
    recovery_ = verdict.recovery;
    recovery_until_ns_ = now_ns + robotio::SecondsToNanos(config_.recovery_s);
    follower_.Stop();
    return {now_ns, 0.0, 0.0};
  }
  const auto plan = mediator_.plan.Get();
  const robotio::Pose2D on_path = PoseOnPath(plan ? &plan->value : nullptr, pose, dt_s);
  if (now_ns < recovery_until_ns_) {
    // Backing off goes where no Kinect looks: the map says what is behind.
    return HoldAtKnownObstacles(plan ? &plan->value : nullptr, pose, on_path,
                                {now_ns, recovery_.v, recovery_.omega});
  }

  // Stand still first (the gyro bias is learnt while the wheels do not move), then look
  // around once before following any plan: the first view is narrow.
  if (start_ns_ < 0) start_ns_ = now_ns;
  if (now_ns - start_ns_ < robotio::SecondsToNanos(config_.initial_still_s)) {
    return {now_ns, 0.0, 0.0};
  }
  if (turned_rad_ < config_.initial_turn_rad) {
    turned_rad_ += config_.look_around_yaw_rate * dt_s;
    return {now_ns, 0.0, config_.look_around_yaw_rate};
  }
  mediator_.counters.looked_around = true;
  if (!plan) return {now_ns, 0.0, 0.0};
  if (plan->version != plan_version_) {
    plan_version_ = plan->version;
    follower_.SetPath(plan->value.path_map, plan->value.look_at_map);
  }
  if (!plan->value.has_goal || plan->value.path_map.empty()) return {now_ns, 0.0, 0.0};
  // The follower slows by the lesser clearance of the two poses (off the grid: the
  // footprint radius).
  double clearance = std::numeric_limits<double>::infinity();
  if (plan->value.map && plan->value.clearance) {
    for (const robotio::Pose2D& p : {pose, on_path}) {
      const planning::GridIndex cell = plan->value.map->CellAt(p.x, p.y);
      if (plan->value.map->Contains(cell)) {
        clearance = std::min(clearance,
                             planning::Clearance(*plan->value.clearance, cell, config_.cost));
      }
    }
  }
  if (!std::isfinite(clearance)) clearance = config_.guard.footprint_radius_m;
  planning::FollowerOutput out = follower_.Step(on_path, clearance, dt_s);
  out.command.stamp_ns = now_ns;
  const robotio::VelocityCommand held =
      HoldAtKnownObstacles(&plan->value, pose, on_path, out.command);
  return GiveUpALongHold(pose, out.command, held, dt_s);
}

robotio::VelocityCommand ControlWorker::GiveUpALongHold(const robotio::Pose2D& pose,
                                                        const robotio::VelocityCommand& wanted,
                                                        robotio::VelocityCommand command,
                                                        double dt_s) {
  if (command.v != 0.0) {
    map_guard_held_s_ = 0.0;  // Driving: whatever held it before is behind.
    return command;
  }
  if (wanted.v == 0.0) return command;  // Turning in place or at rest: nothing held.
  map_guard_held_s_ += dt_s;
  if (map_guard_held_s_ < config_.map_guard_give_up_s) return command;
  // The plan runs into the map where the guard will not let the base go, and nothing the
  // follower does changes that: the planner gets the way ahead blocked, as after a stall,
  // and plans another way or another target.
  map_guard_held_s_ = 0.0;
  ++mediator_.counters.map_guard_give_ups;
  spdlog::debug("t {:.2f} s: the map guard held the base at ({:.2f}, {:.2f}) for {:.1f} s: "
                "the way ahead is reported blocked", robotio::NanosToSeconds(command.stamp_ns),
                pose.x, pose.y, config_.map_guard_give_up_s);
  const double direction = wanted.v < 0.0 ? -1.0 : 1.0;
  mediator_.ReportObstacles(
      planning::StallObstacle(pose, config_.guard.footprint_radius_m, direction));
  follower_.Stop();
  return {command.stamp_ns, 0.0, 0.0};
}

robotio::VelocityCommand ControlWorker::HoldAtKnownObstacles(const Plan* plan,
                                                             const robotio::Pose2D& pose,
                                                             const robotio::Pose2D& on_path,
                                                             robotio::VelocityCommand command) {
  if (plan == nullptr || !plan->map) return command;
  const planning::GridMap& map = *plan->map;
  // The Kinects see nothing within 0.5 m, beside or behind the base, and no floor within
  // robotio::FloorBlindRadius (1.25 m for the shipped rig): door posts passing out of view
  // and a stair pit's edge are checked on the map instead. With the path shifted, SLAM's
  // pose and the shifted one must both run into the map's obstacle: the shift exists
  // because one of them is off the map by up to that much, and holding whenever either
  // did left the base standing for good in a doorway it had been shifted into.
  // A squeezed path is measured with the squeeze's allowance off the footprint too:
  // measured with the full footprint, the guard held the base at the doorway the path was
  // planned through, for good (office seed 2 stood 660 s in front of N2's door,
  // docs/RESULTS.md).
  const double footprint = config_.guard.footprint_radius_m -
                           (plan->squeezed ? planning::SqueezeAllowance(map.resolution_m) : 0.0);
  const auto drives_in = [&](const robotio::Pose2D& p) {
    return planning::DrivesIntoKnownObstacle(map, p, command, footprint, config_.map_guard_s);
  };
  const bool shifted = pose.x != on_path.x || pose.y != on_path.y;
  if (drives_in(pose) && (!shifted || drives_in(on_path))) {
    command.v = 0.0;
    ++mediator_.counters.map_guard_stops;
  }
  return command;
}

robotio::VelocityCommand ControlWorker::Tick(std::int64_t now_ns, double dt_s) {
  last_ = Step(now_ns, dt_s);
  return last_;
}

void ControlWorker::Run() {
  const std::int64_t period_ns = robotio::SecondsToNanos(1.0 / config_.rate_hz);
  std::int64_t next_ns = 0;
  while (mediator_.control.WaitWhilePaused()) {
    if (!mediator_.clock.WaitUntil(next_ns, mediator_.control)) break;
    const std::int64_t now_ns = mediator_.clock.now_ns();
    mediator_.command.Set(Tick(now_ns, 1.0 / config_.rate_hz));
    mediator_.counters.control_done_ns = now_ns;
    next_ns = now_ns + period_ns;
  }
  mediator_.command.Set({mediator_.clock.now_ns(), 0.0, 0.0});
}

}  // namespace dynamap::app::runtime
