#include "dynamap/app/runtime/MappingWorker.hpp"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "Percentile.hpp"
#include "dynamap/mapping/MapFiles.hpp"
#include "dynamap/planning/DualMapView.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::app::runtime {

namespace {
// Rays per image row sampled for the columns a frame looked through and the surfaces it
// saw closely: about one per voxel at the inspection distance, whatever the resolution.
constexpr int kRaysPerRow = 160;

// Longest capture-time span of one scan: three quarters of the fastest Kinect's period,
// as `dynamap map` groups a recording.
std::int64_t ScanSpan(const robotio::Rig& rig) {
  double rate_hz = 0.0;
  for (const auto& k : rig.kinects) rate_hz = std::max(rate_hz, k.rate_hz);
  return rate_hz > 0.0 ? robotio::SecondsToNanos(0.75 / rate_hz) : 0;
}

}  // namespace

MappingWorker::MappingWorker(Mediator& mediator, robotio::Rig rig, MappingWorkerConfig config)
    : mediator_(mediator),
      rig_(std::move(rig)),
      config_(std::move(config)),
      map_(config_.mapping),
      projector_(config_.area, config_.projection),
      accuracy_(config_.mapping.resolution_m, config_.mapping.max_range_m,
                config_.evaluation_stride),
      inspected_(config_.mapping.resolution_m, config_.inspection_distance_m),
      scans_(static_cast<int>(rig_.kinects.size()), ScanSpan(rig_)) {
  if (config_.poses == PoseSource::kSlam) {
    slam_.emplace(config_.slam, config_.mapping, rig_);
    if (config_.slam.loop_closure.enabled) loop_closing_.emplace(config_.slam.loop_closure);
  }
}

MappingWorker::~MappingWorker() = default;

bool MappingWorker::Inspected(const Eigen::Vector3f& p) const { return inspected_.Contains(p); }

void MappingWorker::Score(const CapturedFrame& frame, const robotio::KinectMount& mount,
                          const robotio::Pose2D& T_map_base, const robotio::Pose2D& odometry) {
  const Eigen::Isometry3d T = T_map_base.ToIsometry();
  if (frame.labels) accuracy_.Add(frame.depth, *frame.labels, mount, T);
  // The grid columns the frame looked through (only those can change in the projection)
  // and the surfaces it hit from within the inspection distance.
  const int stride = std::max(1, frame.depth.width / kRaysPerRow);
  const robotio::DepthRays rays = robotio::DepthToRays(frame.depth, mount, T, stride);
  // The surfaces from where the Kinect really was when the simulator says: the coverage
  // is scored against the true surfaces, and marked from an estimate 0.1 m off, a wall
  // seen from 1 m landed a voxel or two beside the true one and counted as missed (an
  // office mission under SLAM, its online estimate 0.16 m RMS off, scored 0.41); the
  // map's error is scored by SA and the ATE.
  // Frames placed at their true pose (or with no truth to place them by) share the rays.
  if (!frame.true_pose || config_.poses == PoseSource::kGroundTruth) {
    inspected_.Add(rays);
  } else {
    inspected_.Add(robotio::DepthToRays(frame.depth, mount, frame.true_pose->ToIsometry(), stride));
  }
  const std::vector<Eigen::Vector2f> columns = planning::TouchedColumns(rays, projector_.map());
  touched_.insert(touched_.end(), columns.begin(), columns.end());
  const std::vector<Eigen::Vector2f> hits = planning::HitColumns(
      rays, projector_.map(), config_.projection.step_height_m, config_.projection.robot_height_m);
  hit_.insert(hit_.end(), hits.begin(), hits.end());
  mediator_.pose_fix.Set({frame.depth.stamp_ns, T_map_base, odometry});
  mediator_.AddEstimate(robotio::ToStampedPose(frame.depth.stamp_ns, T_map_base));
  mediator_.AddOdometryEstimate(robotio::ToStampedPose(frame.depth.stamp_ns, odometry));
  ++mediator_.counters.frames_processed;
}

void MappingWorker::Process(const std::vector<CapturedFrame>& batch) {
  std::vector<const CapturedFrame*> frames;
  std::vector<robotio::Pose2D> odometry;
  for (const CapturedFrame& frame : batch) {
    const auto sensor = static_cast<std::size_t>(frame.depth.sensor_id);
    const auto pose = mediator_.odometry.PoseAt(frame.depth.stamp_ns);
    if (sensor >= rig_.kinects.size() || !pose) continue;  // Cannot be placed yet.
    frames.push_back(&frame);
    odometry.push_back(*pose);
  }
  if (frames.empty()) return;
  const auto start = std::chrono::steady_clock::now();
  std::vector<robotio::Pose2D> placed(frames.size());
  if (slam_) {
    std::vector<robotio::DepthFrame> depths;
    for (const CapturedFrame* f : frames) depths.push_back(f->depth);
    const mapping::SlamStep step = slam_->ProcessScan(depths, odometry);
    if (step.registered) {
      ++(step.accepted ? mediator_.counters.registrations_accepted
                       : mediator_.counters.registrations_rejected);
    }
    // The scan's pose is the first frame's; the others follow by their odometry.
    for (std::size_t i = 0; i < frames.size(); ++i) {
      placed[i] = step.pose.Compose(odometry[0].Between(odometry[i]));
    }
    // A closure moves the pose from the next scan on: this one is in the map where
    // `step.pose` put it.
    if (loop_closing_ &&
        loop_closing_->Offer(frames[0]->depth.stamp_ns, step.pose,
                             slam_->last_registered_scan(), odometry[0],
                             slam_->heading_held_by_walls()) &&
        config_.slam.loop_closure.correct_while_running) {
      if (const auto correction = loop_closing_->CloseNewest()) {
        slam_->ApplyCorrection(*correction);
        ++mediator_.counters.loop_closures;
      }
    }
  } else {
    std::vector<const robotio::DepthFrame*> depths;
    std::vector<robotio::KinectMount> mounts;
    std::vector<Eigen::Isometry3d> poses;
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const bool truth = config_.poses == PoseSource::kGroundTruth && frames[i]->true_pose;
      // The odometry frame starts at the start pose, which is the map frame's origin.
      placed[i] = truth ? *frames[i]->true_pose : odometry[i];
      depths.push_back(&frames[i]->depth);
      mounts.push_back(rig_.kinects[static_cast<std::size_t>(frames[i]->depth.sensor_id)]);
      poses.push_back(placed[i].ToIsometry());
    }
    (void)map_.InsertDepthFrames(depths, mounts, poses);  // One scan: each voxel once.
  }
  insert_ms_.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    Score(*frames[i], rig_.kinects[static_cast<std::size_t>(frames[i]->depth.sensor_id)], placed[i],
          odometry[i]);
  }
}

void MappingWorker::Reproject() {
  const planning::DualMapView view(map());
  const double now_s = robotio::NanosToSeconds(mediator_.clock.now_ns());
  projector_.Refresh(hit_, now_s);
  (void)projector_.Update(view, touched_, now_s);
  (void)projector_.ExpireDynamicObstacles(view, now_s);
  touched_.clear();
  hit_.clear();
  if (mediator_.map_copy_wanted.exchange(false)) {
    mediator_.map_copy.Set(std::shared_ptr<const mapping::DualOcTree>(map().tree().Clone()));
  }
  mediator_.grid.Set(std::make_shared<const ProjectedGrid>(
      ProjectedGrid{projector_.map(), projector_.DynamicObstacleCells()}));
}

void MappingWorker::Run() {
  while (!mediator_.control.stopping()) {
    std::vector<CapturedFrame> frames_taken =
        mediator_.frames.TakeAll(std::chrono::milliseconds(50));
    if (frames_taken.empty()) continue;
    std::int64_t newest_received = -1;
    std::int64_t newest_stamp = -1;
    for (const CapturedFrame& frame : frames_taken) {
      newest_received = std::max(newest_received, frame.depth.received_ns);
      newest_stamp = std::max(newest_stamp, frame.depth.stamp_ns);
    }
    // Frames received count as done once taken: a lone frame waiting for its partner must
    // not hold up a simulation that waits for SLAM.
    for (const std::vector<CapturedFrame>& scan : scans_.Add(std::move(frames_taken))) {
      Process(scan);
    }
    if (!touched_.empty()) Reproject();
    const std::int64_t now = newest_stamp;
    if (!config_.save_file.empty() &&
        now - last_save_ns_ >= static_cast<std::int64_t>(config_.save_period_s * 1e9)) {
      last_save_ns_ = now;
      if (auto status = mapping::SaveDualMap(map().tree(), config_.save_file); !status) {
        spdlog::error("{}", status.error().message);
      }
    }
    mediator_.counters.slam_done_ns = newest_received;
  }
}

void MappingWorker::CloseLoops() {
  if (!loop_closing_ || loops_closed_) return;
  loops_closed_ = true;
  if (config_.slam.loop_closure.correct_while_running) {
    loop_closure_ = loop_closing_->online();
    return;
  }
  loop_closure_ = loop_closing_->Close();
}

robotio::Trajectory MappingWorker::Corrected(const robotio::Trajectory& estimates) const {
  if (!loop_closing_) return estimates;
  robotio::Trajectory corrected = estimates;
  for (robotio::StampedPose& p : corrected) {
    p.pose = loop_closing_->Correct(p.stamp_ns, robotio::Pose2D::FromIsometry(p.pose)).ToIsometry();
  }
  return corrected;
}

mapping::PointAccuracy MappingWorker::Accuracy() const { return accuracy_.Evaluate(map().tree()); }

mapping::MisclassifiedVoxels MappingWorker::Misclassified() const {
  return accuracy_.Misclassified(map().tree());
}

double MappingWorker::median_insert_ms() const { return Percentile(insert_ms_, 0.5); }
double MappingWorker::p95_insert_ms() const { return Percentile(insert_ms_, 0.95); }

}  // namespace dynamap::app::runtime
