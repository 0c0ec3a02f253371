#include "dynamap/mapping/SlamLoop.hpp"

#include <octomap/octomap_types.h>
#include <octomap/octomap_utils.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <utility>

#include "dynamap/mapping/Preprocessing.hpp"

namespace dynamap::mapping {
namespace {

using Clock = std::chrono::steady_clock;
double SecondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

robotio::PointList Transformed(const robotio::PointList& points, const robotio::Pose2D& pose) {
  return TransformedPoints(points, pose.ToIsometry());
}

// The registered pose with its correction removed along directions the scan does not
// constrain (Zhang, Kaess & Singh 2016, solution remapping, here in x/y/yaw).
robotio::Pose2D ConstrainedCorrection(const robotio::Pose2D& predicted,
                                      const robotio::Pose2D& registered,
                                      const Eigen::Matrix3d& information, double ratio) {
  if (ratio <= 0.0 || information.isZero()) return registered;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(information);
  const Eigen::Vector3d values = eigen.eigenvalues();
  if (values.maxCoeff() <= 0.0) return registered;
  const Eigen::Vector3d delta(registered.x - predicted.x, registered.y - predicted.y,
                              robotio::WrapAngle(registered.theta - predicted.theta));
  Eigen::Vector3d kept = Eigen::Vector3d::Zero();
  for (int i = 0; i < 3; ++i) {
    if (values(i) < ratio * values.maxCoeff()) continue;
    const Eigen::Vector3d v = eigen.eigenvectors().col(i);
    kept += v * v.dot(delta);
  }
  return {predicted.x + kept.x(), predicted.y + kept.y(),
          robotio::WrapAngle(predicted.theta + kept.z())};
}

}  // namespace

const char* ReferenceStrategyName(ReferenceStrategy strategy) {
  switch (strategy) {
    case ReferenceStrategy::kPrevious:
      return "previous";
    case ReferenceStrategy::kMap:
      return "map";
    case ReferenceStrategy::kCombined:
      return "combined";
  }
  return "combined";
}

SlamConfig ParseSlamConfig(robotio::ConfigNode& node) {
  SlamConfig config;
  std::string reference = ReferenceStrategyName(config.reference);
  node.ReadChoice("reference", &reference, {"previous", "map", "combined"});
  config.reference = reference == "previous" ? ReferenceStrategy::kPrevious
                     : reference == "map"    ? ReferenceStrategy::kMap
                                             : ReferenceStrategy::kCombined;
  node.Read("filter_dynamic", &config.filter_dynamic);
  node.Read("filter_free_space", &config.filter_free_space);
  node.Read("min_inlier_ratio", &config.min_inlier_ratio, 0.0, 1.0);
  node.Read("max_fitness_rmse_m", &config.max_fitness_rmse_m, 1e-4, 1.0);
  node.Read("max_correction_m", &config.max_correction_m, 0.0, 5.0);
  node.Read("max_correction_per_m", &config.max_correction_per_m, 0.0, 5.0);
  node.Read("max_correction_rad", &config.max_correction_rad, 0.0, 3.2);
  node.Read("max_correction_per_rad", &config.max_correction_per_rad, 0.0, 5.0);
  node.Read("map_reference_radius_m", &config.map_reference_radius_m, 0.5, 50.0);
  node.Read("map_reference_min_probability", &config.map_reference_min_probability, 0.5, 0.99);
  node.Read("map_reference_surface_points", &config.map_reference_surface_points);
  node.Read("reference_refresh_m", &config.reference_refresh_m, 0.0, 10.0);
  node.Read("reference_max_age_s", &config.reference_max_age_s, 0.0, 60.0);
  node.Read("registration_voxel_m", &config.registration_voxel_m, 0.0, 1.0);
  node.Read("registration_max_depth_m", &config.registration_max_depth_m, 0.0, 100.0);
  node.Read("degenerate_eigen_ratio", &config.degenerate_eigen_ratio, 0.0, 1.0);
  node.Read("fuse_with_odometry", &config.fuse_with_odometry);
  node.Read("odometry_sigma_per_sqrt_m", &config.odometry_sigma_per_sqrt_m, 0.0, 1.0);
  node.Read("odometry_sigma_per_sqrt_rad", &config.odometry_sigma_per_sqrt_rad, 0.0, 1.0);
  node.Read("heading_sigma_per_sqrt_s", &config.heading_sigma_per_sqrt_s, 0.0, 1.0);
  node.Read("registration_sigma_m", &config.registration_sigma_m, 1e-6, 1.0);
  node.Read("registration_sigma_rad", &config.registration_sigma_rad, 1e-6, 1.0);
  int min_scan = static_cast<int>(config.min_scan_points);
  int min_reference = static_cast<int>(config.min_reference_points);
  node.Read("min_scan_points", &min_scan, 10, 1'000'000);
  node.Read("min_reference_points", &min_reference, 10, 10'000'000);
  config.min_scan_points = static_cast<std::size_t>(min_scan);
  config.min_reference_points = static_cast<std::size_t>(min_reference);
  if (auto registration = node.OptionalChild("registration")) {
    config.registration = ParseRegistrationConfig(*registration);
  }
  if (auto wall_heading = node.OptionalChild("wall_heading")) {
    config.wall_heading = ParseWallHeadingConfig(*wall_heading);
  }
  if (auto loop_closure = node.OptionalChild("loop_closure")) {
    config.loop_closure = ParseLoopClosureConfig(*loop_closure);
  }
  return config;
}

robotio::Expected<SlamConfig> LoadSlamConfig(const std::string& file) {
  return robotio::ParseYamlFile<SlamConfig>(
      file, [](robotio::ConfigNode& node) { return ParseSlamConfig(node); });
}

robotio::Rig RegistrationRig(robotio::Rig rig, const SlamConfig& slam,
                             const MappingConfig& mapping) {
  for (auto& mount : rig.kinects) {
    mount.max_range_m = std::min(mount.max_range_m, mapping.max_range_m);
    if (slam.registration_max_depth_m > 0.0) {
      mount.max_range_m = std::min(mount.max_range_m, slam.registration_max_depth_m);
    }
  }
  return rig;
}

robotio::PointList ScanPointsInMap(const std::vector<robotio::DepthFrame>& frames,
                                   const std::vector<robotio::Pose2D>& frame_offsets,
                                   const robotio::Rig& rig, const robotio::Pose2D& at_scan,
                                   double voxel_m) {
  robotio::PointList merged;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto sensor = static_cast<std::size_t>(frames[k].sensor_id);
    if (sensor >= rig.kinects.size()) continue;
    const robotio::PointList points =
        Transformed(robotio::DepthToBasePoints(frames[k], rig.kinects[sensor]), frame_offsets[k]);
    merged.insert(merged.end(), points.begin(), points.end());
  }
  // Thinned on a grid fixed in the map (at the scan's pose), not on one fixed to the
  // robot: voxel centroids of a robot-fixed grid sit at the same place in the robot frame
  // scan after scan, a lattice that moves with the robot and pulls registration towards
  // no motion (scan-to-scan ICP took 10 % off the distance driven on the office tour; see
  // docs/RESULTS.md). On a map-fixed grid that lattice stays put like the walls.
  return VoxelGridFilter(Transformed(merged, at_scan), voxel_m);
}

SlamLoop::SlamLoop(SlamConfig config, const MappingConfig& mapping, robotio::Rig rig)
    : config_(std::move(config)),
      rig_(std::move(rig)),
      map_(mapping),
      map_registration_(config_.registration),
      previous_registration_(config_.registration) {
  for (auto& mount : rig_.kinects) {
    mount.max_range_m = std::min(mount.max_range_m, mapping.max_range_m);
  }
  scan_rig_ = RegistrationRig(rig_, config_, mapping);
  if (config_.wall_heading.enabled && config_.fuse_with_odometry) {
    wall_heading_.emplace(config_.wall_heading);
  }
}

robotio::PointList SlamLoop::MapReference(const robotio::Pose2D& around) const {
  const DualOcTree& tree = map_.tree();
  robotio::PointList points;
  if (tree.getRoot() == nullptr) return points;
  const auto r = static_cast<float>(config_.map_reference_radius_m);
  const octomap::point3d min(static_cast<float>(around.x) - r, static_cast<float>(around.y) - r,
                             -100.0f);
  const octomap::point3d max(static_cast<float>(around.x) + r, static_cast<float>(around.y) + r,
                             100.0f);
  const float min_log_odds =
      octomap::logodds(static_cast<float>(config_.map_reference_min_probability));
  const unsigned leaf_depth = tree.getTreeDepth();
  for (auto it = tree.begin_leafs_bbx(min, max), end = tree.end_leafs_bbx(); it != end; ++it) {
    if (!tree.IsStaticOccupied(*it) || it->StaticLogOdds() < min_log_odds) continue;
    if (config_.map_reference_surface_points && it.getDepth() == leaf_depth) {
      const auto sample = surface_samples_.find(it.getKey());
      if (sample != surface_samples_.end()) {
        points.push_back(sample->second.sum / sample->second.count);
        continue;
      }
    }
    const octomap::point3d c = it.getCoordinate();
    points.emplace_back(c.x(), c.y(), c.z());
  }
  if (config_.registration_voxel_m > 0.0)
    return VoxelGridFilter(points, config_.registration_voxel_m);
  return points;
}

void SlamLoop::AddSurfaceSamples(const robotio::PointList& scan_map) {
  // Up to this many points a voxel's mean is their plain mean; after it, each new point
  // weighs 1/kMaxSamples, so a voxel follows what recent scans saw without forgetting fast.
  constexpr float kMaxSamples = 20.0f;
  const DualOcTree& tree = map_.tree();
  for (const auto& p : scan_map) {
    octomap::OcTreeKey key;
    if (!tree.coordToKeyChecked(p.x(), p.y(), p.z(), key)) continue;
    SurfaceSample& sample = surface_samples_[key];
    if (sample.count < kMaxSamples) {
      sample.sum += p;
      sample.count += 1.0f;
    } else {
      sample.sum += p - sample.sum / sample.count;
    }
  }
}

bool SlamLoop::UpdateMapTarget(const robotio::Pose2D& predicted, std::int64_t stamp_ns) {
  const bool fresh =
      reference_centre_ &&
      std::hypot(predicted.x - reference_centre_->x, predicted.y - reference_centre_->y) <
          config_.reference_refresh_m &&
      static_cast<double>(stamp_ns - reference_stamp_ns_) * 1e-9 < config_.reference_max_age_s;
  if (fresh) return false;
  map_registration_.SetTarget(MapReference(predicted));
  reference_centre_ = predicted;
  reference_stamp_ns_ = stamp_ns;
  return true;
}

robotio::Pose2D SlamLoop::Fuse(const robotio::Pose2D& predicted,
                               const robotio::Pose2D& registered) {
  if (!config_.fuse_with_odometry) return registered;
  const double r_xy = config_.registration_sigma_m * config_.registration_sigma_m;
  const double r_theta = config_.registration_sigma_rad * config_.registration_sigma_rad;
  const double k_xy = position_variance_ / (position_variance_ + r_xy);
  const double k_theta = heading_variance_ / (heading_variance_ + r_theta);
  position_variance_ *= 1.0 - k_xy;
  heading_variance_ *= 1.0 - k_theta;
  return {predicted.x + k_xy * (registered.x - predicted.x),
          predicted.y + k_xy * (registered.y - predicted.y),
          robotio::WrapAngle(predicted.theta +
                             k_theta * robotio::WrapAngle(registered.theta - predicted.theta))};
}

std::optional<double> SlamLoop::FuseWallHeading(const robotio::PointList& scan_base,
                                                robotio::Pose2D* pose) {
  const std::optional<double> measured = wall_heading_->Measure(scan_base, pose->theta);
  if (!measured) return std::nullopt;
  const double r = config_.wall_heading.sigma_rad * config_.wall_heading.sigma_rad;
  const double k = heading_variance_ / (heading_variance_ + r);
  heading_variance_ *= 1.0 - k;
  pose->theta = robotio::WrapAngle(pose->theta + k * robotio::WrapAngle(*measured - pose->theta));
  return measured;
}

bool SlamLoop::heading_held_by_walls() const {
  return last_wall_stamp_ns_ &&
         static_cast<double>(last_stamp_ns_ - *last_wall_stamp_ns_) * 1e-9 <=
             config_.wall_heading.holds_heading_s;
}

bool SlamLoop::Acceptable(const RegistrationResult& result, const robotio::Pose2D& predicted,
                          const robotio::Pose2D& corrected, const Motion& since) const {
  if (!result.converged || result.inlier_ratio < config_.min_inlier_ratio ||
      result.fitness_rmse_m > config_.max_fitness_rmse_m) {
    return false;
  }
  // The gyro and wheels are good over short motions: a correction much larger than what
  // they could have got wrong is a registration into the wrong minimum. Only the
  // directions the scan constrains count (along a corridor ICP slides freely).
  const robotio::Pose2D correction = predicted.Between(corrected);
  return std::hypot(correction.x, correction.y) <=
             config_.max_correction_m + config_.max_correction_per_m * since.driven_m &&
         std::abs(correction.theta) <=
             config_.max_correction_rad + config_.max_correction_per_rad * since.turned_rad;
}

SlamStep SlamLoop::ProcessScan(const std::vector<robotio::DepthFrame>& frames,
                               const std::vector<robotio::Pose2D>& odometry_at_frames) {
  SlamStep step;
  if (frames.empty() || frames.size() != odometry_at_frames.size()) {
    step.predicted = step.pose = pose_;
    return step;
  }
  // Algorithm 4, lines 2-4: add the odometry increment since the last scan.
  const robotio::Pose2D& odometry = odometry_at_frames.front();
  // The map frame is the odometry frame: the first scan is placed where odometry says.
  const robotio::Pose2D increment =
      last_odometry_ ? last_odometry_->Between(odometry) : robotio::Pose2D{};
  step.predicted = last_odometry_ ? pose_.Compose(increment) : odometry;
  last_odometry_ = odometry;
  // What odometry and gyro may have got wrong over this increment (fusion prior).
  const std::int64_t stamp_ns = frames.front().stamp_ns;
  const double elapsed_s =
      last_stamp_ns_ >= 0 ? std::max(0.0, static_cast<double>(stamp_ns - last_stamp_ns_) * 1e-9)
                          : 0.0;
  last_stamp_ns_ = stamp_ns;
  position_variance_ += config_.odometry_sigma_per_sqrt_m * config_.odometry_sigma_per_sqrt_m *
                        std::hypot(increment.x, increment.y);
  heading_variance_ +=
      config_.odometry_sigma_per_sqrt_rad * config_.odometry_sigma_per_sqrt_rad *
          std::abs(increment.theta) +
      config_.heading_sigma_per_sqrt_s * config_.heading_sigma_per_sqrt_s * elapsed_s;

  // Line 5: both Kinects in base at the scan's time, voxel filter, dynamic points out.
  auto t = Clock::now();
  std::vector<robotio::Pose2D> frame_offsets;  // base at the scan time ← base at frame k.
  for (const robotio::Pose2D& at_frame : odometry_at_frames) {
    frame_offsets.push_back(odometry.Between(at_frame));
  }
  const Eigen::Isometry3d identity = Eigen::Isometry3d::Identity();
  robotio::PointList scan_map = ScanPointsInMap(frames, frame_offsets, scan_rig_, step.predicted,
                                                map_.config().voxel_filter_m);
  if (config_.filter_dynamic && config_.filter_free_space) {
    scan_map = RemovePointsOfChange(scan_map, map_, identity);
  } else if (config_.filter_dynamic) {
    scan_map = RemoveDynamicPoints(scan_map, map_, identity);
  }
  step.scan_points = scan_map.size();
  step.preprocess_s = SecondsSince(t);

  // Lines 6-10: register against the selected reference, keep a plausible correction.
  t = Clock::now();
  step.pose = step.predicted;
  // Thinned for ICP: a coarser scan and target register as well (the map update below
  // uses every pixel) in a fraction of the time. ICP takes the scan in the base frame.
  robotio::PointList sparse = Transformed(
      config_.registration_voxel_m > 0.0 ? VoxelGridFilter(scan_map, config_.registration_voxel_m)
                                         : scan_map,
      step.predicted.Inverse());
  // A map registration is checked against odometry alone since the last accepted one
  // (with what odometry may have got wrong over that motion): neither scan-to-scan
  // corrections in between nor a stretch without a usable map can lock it out. A
  // previous-scan registration is checked against this scan's prediction.
  const Motion scan_motion{std::hypot(increment.x, increment.y), std::abs(increment.theta)};
  map_motion_.driven_m += scan_motion.driven_m;
  map_motion_.turned_rad += scan_motion.turned_rad;
  map_prediction_ = map_prediction_ ? map_prediction_->Compose(increment) : step.predicted;
  auto try_reference = [&](const Registration& registration, const char* name,
                           const robotio::Pose2D& prediction, const Motion& motion) {
    if (registration.target_size() < config_.min_reference_points) return false;
    step.registration = registration.Align(sparse, step.predicted.ToIsometry());
    step.registered = true;
    step.reference = name;
    const robotio::Pose2D corrected = ConstrainedCorrection(
        prediction, robotio::Pose2D::FromIsometry(step.registration.T_target_source),
        step.registration.planar_information, config_.degenerate_eigen_ratio);
    if (!Acceptable(step.registration, prediction, corrected, motion)) return false;
    step.pose = Fuse(step.predicted, corrected);
    step.accepted = true;
    return true;
  };
  if (scan_map.size() >= config_.min_scan_points) {
    const bool use_map = config_.reference != ReferenceStrategy::kPrevious;
    const bool use_previous = config_.reference != ReferenceStrategy::kMap;
    bool done = false;
    if (use_map) {
      step.reference_rebuilt = UpdateMapTarget(step.predicted, frames.front().stamp_ns);
      done = try_reference(map_registration_, "map", *map_prediction_, map_motion_);
    }
    if (!done && use_previous) {
      previous_registration_.SetTarget(previous_scan_map_);
      try_reference(previous_registration_, "previous", step.predicted, scan_motion);
    }
  }
  // The walls' heading: from the scan before thinning, moved back into the base frame.
  if (wall_heading_) {
    step.wall_heading_rad =
        FuseWallHeading(Transformed(scan_map, step.predicted.Inverse()), &step.pose);
    if (step.wall_heading_rad) last_wall_stamp_ns_ = frames.front().stamp_ns;
  }
  step.register_s = SecondsSince(t);
  pose_ = step.pose;
  if (step.accepted && step.reference == "map") {
    map_prediction_ = pose_;
    map_motion_ = {};
  }

  // Line 11: both maps from the corrected pose, every frame at its own capture time.
  t = Clock::now();
  std::vector<const robotio::DepthFrame*> insert;
  std::vector<robotio::KinectMount> mounts;
  std::vector<Eigen::Isometry3d> placed;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const auto sensor = static_cast<std::size_t>(frames[k].sensor_id);
    if (sensor >= rig_.kinects.size()) continue;
    insert.push_back(&frames[k]);
    mounts.push_back(rig_.kinects[sensor]);
    placed.push_back(pose_.Compose(frame_offsets[k]).ToIsometry());
  }
  map_.InsertDepthFrames(insert, mounts, placed);  // One scan: each voxel updated once.
  if (config_.map_reference_surface_points) {
    // The preprocessed scan was placed at the prediction; move it by the correction.
    AddSurfaceSamples(Transformed(scan_map, pose_.Compose(step.predicted.Inverse())));
  }
  previous_scan_map_ = Transformed(sparse, pose_);
  last_scan_ = std::move(sparse);
  step.update_s = SecondsSince(t);
  return step;
}

void SlamLoop::ApplyCorrection(const robotio::Pose2D& correction) {
  pose_ = correction.Compose(pose_);
  if (map_prediction_) map_prediction_ = correction.Compose(*map_prediction_);
  previous_scan_map_ = Transformed(previous_scan_map_, correction);
  reference_centre_.reset();
}

std::vector<std::vector<std::size_t>> GroupIntoScans(
    const std::vector<std::int64_t>& capture_stamps_ns, const std::vector<int>& sensor_ids,
    std::int64_t max_span_ns) {
  std::vector<std::vector<std::size_t>> scans;
  std::int64_t group_start = 0;
  for (std::size_t i = 0; i < capture_stamps_ns.size(); ++i) {
    bool fits = !scans.empty() && capture_stamps_ns[i] - group_start <= max_span_ns;
    if (fits) {
      for (std::size_t j : scans.back()) fits = fits && sensor_ids[j] != sensor_ids[i];
    }
    if (!fits) {
      scans.emplace_back();
      group_start = capture_stamps_ns[i];
    }
    scans.back().push_back(i);
  }
  return scans;
}

}  // namespace dynamap::mapping
