#include "dynamap/app/runtime/SimulationDriver.hpp"

#include <spdlog/spdlog.h>

#include <thread>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {

SimulationDriver::SimulationDriver(std::unique_ptr<robotio::sim::Simulator> simulator,
                                   Mediator& mediator, SimulationDriverConfig config,
                                   robotio::RecordingWriter* recording)
    : simulator_(std::move(simulator)),
      mediator_(mediator),
      config_(config),
      recording_(recording) {}

void SimulationDriver::Publish(robotio::sim::SimOutput& out) {
  mediator_.odometry.Add(out.odometry, out.imu);
  mediator_.AddGroundTruth(out.ground_truth);
  mediator_.counters.collisions += static_cast<std::int64_t>(out.collisions.size());
  for (const auto& collision : out.collisions) {
    spdlog::warn("collision with {} at t = {:.2f} s", collision.object_id,
                 robotio::NanosToSeconds(collision.stamp_ns));
  }
  if (recording_ != nullptr) {
    bool ok = true;
    for (const auto& r : out.odometry) ok = recording_->AddOdometry(r).ok() && ok;
    for (const auto& r : out.imu) ok = recording_->AddImu(r).ok() && ok;
    for (const auto& p : out.ground_truth) ok = recording_->AddGroundTruth(p).ok() && ok;
    for (const auto& f : out.frames) {
      ok = recording_->AddDepth(f.depth).ok() && ok;
      ok = recording_->AddLabels(f.labels, f.depth.received_ns).ok() && ok;
    }
    if (!ok) ++recording_errors_;
  }
  for (auto& f : out.frames) {
    const int sensor = f.depth.sensor_id;
    if (sensor >= 0 && sensor < kMaxKinects) mediator_.latest_depth[sensor].Set(f.depth);
    mediator_.counters.last_frame_received_ns = f.depth.received_ns;
    const auto& mount = simulator_->rig().kinects.at(static_cast<std::size_t>(sensor));
    const robotio::Pose2D true_pose = robotio::Pose2D::FromIsometry(
        f.T_map_kinect.pose * mount.T_base_kinect.inverse());
    mediator_.frames.Push(CapturedFrame{std::move(f.depth), std::move(f.labels), true_pose});
  }
}

void SimulationDriver::Run() {
  const auto step_ns = static_cast<std::int64_t>(config_.step_s * 1e9);
  const auto end_ns = static_cast<std::int64_t>(config_.max_time_s * 1e9);
  std::int64_t t_ns = simulator_->now_ns();
  for (;;) {
    const bool was_paused = mediator_.control.state() == MissionState::kPaused;
    if (!mediator_.control.WaitWhilePaused()) break;
    if (was_paused) mediator_.clock.Reanchor();  // No racing to catch up after a pause.
    if (mediator_.control.state() == MissionState::kRunning && !mediator_.clock.paced()) {
      if (!mediator_.WaitForWorkers(t_ns, config_.control_period_s, config_.replan_period_s)) break;
    }
    if (t_ns >= end_ns) {
      reached_time_limit_ = true;
      break;
    }
    if (const auto command = mediator_.command.Get()) simulator_->SetCommand(command->value);
    t_ns += step_ns;
    robotio::sim::SimOutput out = simulator_->AdvanceTo(t_ns);
    Publish(out);
    mediator_.clock.AdvanceTo(t_ns);
  }
  // Whatever ended the loop, the base is told to stop.
  simulator_->SetCommand({t_ns, 0.0, 0.0});
}

}  // namespace dynamap::app::runtime
