#include "dynamap/robotio/sim/Simulator.hpp"

#include <algorithm>
#include <cmath>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::robotio::sim {

namespace {

constexpr double kContactRelease = 0.005;  // m of clearance that ends a contact.

std::int64_t CaptureTime(const KinectMount& mount, int sensor, int sensors, bool stagger,
                         std::int64_t index) {
  const double period = 1.0 / mount.rate_hz;
  const double phase = stagger ? period * sensor / sensors : 0.0;
  return SecondsToNanos(phase + period * static_cast<double>(index));
}

}  // namespace

Simulator::Simulator(World world, RobotConfig robot, Rig rig, SimulatorConfig config)
    : world_(std::move(world)),
      robot_(std::move(robot)),
      rig_(std::move(rig)),
      config_(config),
      base_(robot_, world_.robot_start, HashKey(config.seed, 0xBA5E)),
      collision_world_(world_, robot_.height_m),
      step_ns_(std::max<std::int64_t>(1000, SecondsToNanos(config.physics_step_s))),
      frame_index_(rig_.kinects.size(), 0),
      clocks_{std::vector<double>(world_.people.size(), 0.0),
              std::vector<double>(world_.doors.size(), 0.0),
              std::vector<double>(world_.furniture.size(), 0.0)},
      yielding_(world_.people.size()) {
  if (config_.render_depth && !rig_.kinects.empty()) {
    renderer_ = std::make_unique<DepthRenderer>(world_, config_.render_threads);
  }
}

void Simulator::SetCommand(const VelocityCommand& command) {
  base_.SetCommand(command.v, command.omega);
}

Pose2D Simulator::TruePose() const { return world_.ToMap(base_.pose_world()); }

std::uint64_t Simulator::rays_cast() const { return renderer_ ? renderer_->rays_cast() : 0; }

SimOutput Simulator::Advance(double dt_s) { return AdvanceTo(now_ns_ + SecondsToNanos(dt_s)); }

SimOutput Simulator::AdvanceTo(std::int64_t t_ns) {
  SimOutput out;
  if (now_ns_ == 0 && next_imu_ns_ == 0) {
    // The readings of the start instant.
    out.odometry.push_back(base_.Odometry(0));
    out.imu.push_back(base_.Imu(0, imu_count_++));
    out.ground_truth.push_back(ToStampedPose(0, TruePose()));
    next_imu_ns_ = SecondsToNanos(1.0 / robot_.imu_rate_hz);
    next_odometry_ns_ = SecondsToNanos(1.0 / robot_.odometry_rate_hz);
  }
  while (now_ns_ < t_ns) Step(&out);
  return out;
}

void Simulator::Step(SimOutput* out) {
  const std::int64_t t0 = now_ns_;
  const std::int64_t t1 = t0 + step_ns_;
  const double dt = NanosToSeconds(step_ns_);
  const Pose2D pose0 = base_.pose_world();
  const double t1_s = NanosToSeconds(t1);

  // Collision: accept a motion that keeps the footprint free, that does not push it deeper
  // into an overlap (a person may walk into a standing robot) or that only turns it (the
  // footprint is a circle); otherwise the base stops moving ahead and only turns, so a
  // robot pressed against a door post while turning towards its path can turn free.
  const Pose2D proposed = base_.Propose(dt);
  const double radius = robot_.footprint_radius_m;
  const Contact now = collision_world_.Check({pose0.x, pose0.y}, radius, t1_s, &clocks_);
  const Contact next =
      collision_world_.Check({proposed.x, proposed.y}, radius, t1_s, &clocks_);
  const bool moving = std::abs(proposed.x - pose0.x) + std::abs(proposed.y - pose0.y) > 1e-12;
  const bool blocked = moving && next.clearance_m < 0.0 && next.clearance_m < now.clearance_m;
  const bool touching = now.clearance_m < 0.0 || (moving && next.clearance_m < 0.0);
  if (blocked) {
    base_.TurnOnly(dt);
  } else {
    base_.Move(dt);
  }
  if (touching) {
    if (!in_contact_) {
      in_contact_ = true;
      ++collisions_;
      const Contact& c = next.clearance_m < 0.0 ? next : now;
      CollisionEvent event;
      event.stamp_ns = t1;
      event.object_id = world_.objects[c.object_index].id;
      event.kind = world_.objects[c.object_index].kind;
      event.pose = TruePose();
      out->collisions.push_back(event);
    }
  } else if (next.clearance_m > kContactRelease) {
    in_contact_ = false;
  }
  now_ns_ = t1;
  const Pose2D pose1 = base_.pose_world();
  AdvancePeople(dt, pose1);
  AdvanceDoorsAndFurniture(dt, pose1);

  if (renderer_) {
    const int sensors = static_cast<int>(rig_.kinects.size());
    for (int i = 0; i < sensors; ++i) {
      for (;;) {
        const std::int64_t capture =
            CaptureTime(rig_.kinects[i], i, sensors, config_.stagger_kinects, frame_index_[i]);
        if (capture > t1) break;
        const double s = static_cast<double>(capture - t0) / static_cast<double>(step_ns_);
        pending_.push_back(Capture(i, capture, Interpolate(pose0, pose1, std::clamp(s, 0.0, 1.0))));
        ++frame_index_[i];
      }
    }
    std::stable_sort(pending_.begin(), pending_.end(), [](const SimFrame& a, const SimFrame& b) {
      return a.depth.received_ns < b.depth.received_ns;
    });
    auto delivered = pending_.begin();
    while (delivered != pending_.end() && delivered->depth.received_ns <= now_ns_) ++delivered;
    for (auto it = pending_.begin(); it != delivered; ++it) out->frames.push_back(std::move(*it));
    pending_.erase(pending_.begin(), delivered);
  }
  while (next_imu_ns_ <= now_ns_) {
    out->imu.push_back(base_.Imu(next_imu_ns_, imu_count_++));
    out->ground_truth.push_back(ToStampedPose(next_imu_ns_, TruePose()));
    next_imu_ns_ = SecondsToNanos(static_cast<double>(imu_count_) / robot_.imu_rate_hz);
  }
  while (next_odometry_ns_ <= now_ns_) {
    out->odometry.push_back(base_.Odometry(next_odometry_ns_));
    next_odometry_ns_ += SecondsToNanos(1.0 / robot_.odometry_rate_hz);
  }
}

void Simulator::AdvancePeople(double dt_s, const Pose2D& robot_world) {
  const Eigen::Vector2d robot(robot_world.x, robot_world.y);
  const double radius = robot_.footprint_radius_m;
  const double now_s = NanosToSeconds(now_ns_);
  for (std::size_t i = 0; i < world_.people.size(); ++i) {
    const Person& person = world_.people[i];
    double& clock = clocks_.people_s[i];
    Yielding& y = yielding_[i];
    if (!person.yields) {
      clock += dt_s;
      continue;
    }
    const auto clearance = [&](double t) {
      return collision_world_.PersonClearance(person, PersonAt(person, t), robot, radius);
    };
    const double here = clearance(clock);
    const bool can_step_back = clock >= dt_s && clearance(clock - dt_s) > here;
    if (y.giving_way) {
      // Back the way it came, far enough for the robot to pass, then it stands a while.
      if (here < config_.give_way_clearance_m && can_step_back) {
        clock -= dt_s;
        continue;
      }
      y.giving_way = false;
      y.waited_s = 0.0;
      y.stand_until_s = now_s + config_.yield_patience_s;
    }
    if (now_s < y.stand_until_s && here < config_.give_way_clearance_m) continue;
    const double ahead = clearance(clock + dt_s);
    if (ahead < config_.yield_clearance_m && ahead < here) {
      // The step would bring it nearer to the robot than it likes. With the robot already
      // that near (it came closer) it backs off; otherwise it waits, and gives way when
      // the robot stays in its way.
      y.waited_s += dt_s;
      if (here < config_.yield_clearance_m && can_step_back) {
        clock -= dt_s;
      } else if (y.waited_s > config_.yield_patience_s) {
        y.giving_way = true;
      }
      continue;
    }
    y.waited_s = 0.0;
    clock += dt_s;
  }
}

void Simulator::AdvanceDoorsAndFurniture(double dt_s, const Pose2D& robot_world) {
  const Eigen::Vector2d robot(robot_world.x, robot_world.y);
  const double radius = robot_.footprint_radius_m + config_.schedule_clearance_m;
  const auto overlaps = [&](const std::vector<Solid>& solids) {
    return collision_world_.CheckSolids(solids, robot, radius).clearance_m < 0.0;
  };
  for (std::size_t i = 0; i < world_.doors.size(); ++i) {
    const Door& door = world_.doors[i];
    double& clock = clocks_.doors_s[i];
    const bool next = DoorOpenAt(door, clock + dt_s);
    if (next != DoorOpenAt(door, clock) && overlaps(DoorSolids(door, next))) continue;
    clock += dt_s;
  }
  for (std::size_t i = 0; i < world_.furniture.size(); ++i) {
    const Furniture& furniture = world_.furniture[i];
    double& clock = clocks_.furniture_s[i];
    const Pose2D now = FurniturePoseAt(furniture, clock);
    const Pose2D next = FurniturePoseAt(furniture, clock + dt_s);
    const bool moves = next.x != now.x || next.y != now.y || next.theta != now.theta;
    if (moves && overlaps(FurnitureSolids(furniture, next))) continue;
    clock += dt_s;
  }
}

SimFrame Simulator::Capture(int sensor, std::int64_t capture_ns, const Pose2D& pose_world) {
  if (moving_solids_ns_ != capture_ns) {
    // People as they stand now (within one physics step of the capture instant).
    renderer_->SetMovingSolids(
        MovingSolidsAt(world_, NanosToSeconds(capture_ns), &clocks_));
    moving_solids_ns_ = capture_ns;
  }
  const KinectMount& mount = rig_.kinects[sensor];
  const Eigen::Isometry3d T_world_kinect = pose_world.ToIsometry() * mount.T_base_kinect;
  const std::uint64_t key =
      HashKey(HashKey(config_.seed, static_cast<std::uint64_t>(sensor) + 1),
              static_cast<std::uint64_t>(frame_index_[sensor]));
  RenderedImage image = renderer_->Render(T_world_kinect, mount.intrinsics, mount.min_range_m,
                                          config_.kinect, key);
  SimFrame frame;
  frame.depth = std::move(image.depth);
  frame.depth.sensor_id = sensor;
  frame.depth.stamp_ns = capture_ns;
  frame.depth.received_ns = capture_ns + SecondsToNanos(mount.latency_s);
  frame.labels = std::move(image.labels);
  frame.labels.sensor_id = sensor;
  frame.labels.stamp_ns = capture_ns;
  frame.T_map_kinect.stamp_ns = capture_ns;
  frame.T_map_kinect.pose = world_.T_map_world() * T_world_kinect;
  return frame;
}

}  // namespace dynamap::robotio::sim
