#include "dynamap/app/runtime/RecordingDriver.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <thread>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {

RecordingDriver::RecordingDriver(const robotio::RecordingReader& reader, Mediator& mediator,
                                 RecordingDriverConfig config)
    : reader_(reader), mediator_(mediator), config_(config) {
  for (const robotio::StampedPose& p : reader_.ground_truth()) {
    truth_.push_back({p.stamp_ns, robotio::Pose2D::FromIsometry(p.pose)});
  }
  end_ns_ = reader_.last_stamp_ns();
}

bool RecordingDriver::PublishUpTo(std::int64_t t_ns) {
  std::vector<robotio::OdometryReading> odometry;
  std::vector<robotio::ImuReading> imu;
  std::vector<robotio::StampedPose> truth;
  const auto& all_odometry = reader_.odometry();
  while (next_odometry_ < all_odometry.size() && all_odometry[next_odometry_].stamp_ns <= t_ns) {
    odometry.push_back(all_odometry[next_odometry_++]);
  }
  const auto& all_imu = reader_.imu();
  while (next_imu_ < all_imu.size() && all_imu[next_imu_].stamp_ns <= t_ns) {
    imu.push_back(all_imu[next_imu_++]);
  }
  const auto& all_truth = reader_.ground_truth();
  while (next_truth_ < all_truth.size() && all_truth[next_truth_].stamp_ns <= t_ns) {
    truth.push_back(all_truth[next_truth_++]);
  }
  mediator_.odometry.Add(odometry, imu);
  if (!truth.empty()) mediator_.AddGroundTruth(truth);

  const auto& entries = reader_.depth_entries();
  while (next_frame_ < entries.size() && entries[next_frame_].received_ns <= t_ns) {
    const robotio::DepthEntry& entry = entries[next_frame_++];
    auto depth = reader_.LoadDepth(entry);
    if (!depth) {
      error_ = depth.error().message;
      return false;
    }
    CapturedFrame frame{std::move(*depth), reader_.LoadLabels(entry), std::nullopt};
    if (!truth_.empty()) frame.true_pose = mapping::PoseAt(truth_, frame.depth.stamp_ns);
    const int sensor = frame.depth.sensor_id;
    if (sensor >= 0 && sensor < kMaxKinects) mediator_.latest_depth[sensor].Set(frame.depth);
    mediator_.counters.last_frame_received_ns = frame.depth.received_ns;
    mediator_.frames.Push(std::move(frame));
  }
  return true;
}

void RecordingDriver::Run() {
  const auto step_ns = static_cast<std::int64_t>(config_.step_s * 1e9);
  const std::int64_t end_ns =
      std::min(end_ns_, static_cast<std::int64_t>(config_.max_time_s * 1e9));
  std::int64_t t_ns = 0;
  for (;;) {
    const bool was_paused = mediator_.control.state() == MissionState::kPaused;
    if (!mediator_.control.WaitWhilePaused()) break;
    if (was_paused) mediator_.clock.Reanchor();
    if (mediator_.control.state() == MissionState::kRunning && !mediator_.clock.paced()) {
      if (!mediator_.WaitForWorkers(t_ns, config_.control_period_s, config_.replan_period_s)) break;
    }
    if (t_ns > end_ns) {
      reached_end_ = true;
      break;
    }
    t_ns += step_ns;
    if (!PublishUpTo(t_ns)) {
      spdlog::error("replay ended: {}", *error_);
      break;
    }
    mediator_.clock.AdvanceTo(t_ns);
  }
}

}  // namespace dynamap::app::runtime
