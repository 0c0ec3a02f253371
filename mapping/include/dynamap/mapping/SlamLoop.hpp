// The SLAM loop (thesis 5.3, Algorithm 4): odometry + gyro prediction, preprocessing of
// both Kinects' scans, registration against the previous scan, the map or both, a
// plausibility gate on the correction, then the dual-map update from the corrected pose.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/mapping/LoopClosure.hpp"
#include "dynamap/mapping/MappingConfig.hpp"
#include "dynamap/mapping/Registration.hpp"
#include "dynamap/mapping/WallHeading.hpp"
#include "dynamap/robotio/ConfigReader.hpp"
#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::mapping {

// Where the registration target comes from (thesis 5.3, SelectReferenceScan).
enum class ReferenceStrategy {
  kPrevious,  // The previous preprocessed scan, placed with its corrected pose.
  kMap,       // Occupied static voxel centres near the robot.
  kCombined,  // The map first; the previous scan when the map registration is rejected.
};
[[nodiscard]] const char* ReferenceStrategyName(ReferenceStrategy strategy);

struct SlamConfig {
  ReferenceStrategy reference = ReferenceStrategy::kCombined;
  RegistrationConfig registration;  // ICP settings (planar point-to-plane by default).
  // Drop scan points in dynamic-occupied voxels before registering (thesis 5.3).
  bool filter_dynamic = true;
  // Also drop points in voxels the static map holds as free (RemovePointsOfChange): a
  // person walking into view is in seen-free space before the dynamic map knows them.
  bool filter_free_space = false;
  double min_inlier_ratio = 0.6;     // Share of scan points with a partner, to accept.
  double max_fitness_rmse_m = 0.06;  // m, RMS point distance after ICP, to accept.
  // Plausibility: the correction to odometry (in the directions the scan constrains) may
  // not exceed abs + per-metre · distance driven (and likewise for heading) since the
  // last accepted map registration (map target) or the last scan (previous scan).
  double max_correction_m = 0.01;       // m.
  // 0.1: with 0.2 the office tour took a 0.29 m wrong correction after 2.3 m without an
  // accepted map registration (docs/RESULTS.md).
  double max_correction_per_m = 0.1;    // m per m driven.
  double max_correction_rad = 0.005;    // rad.
  double max_correction_per_rad = 0.2;  // rad per rad turned (gyro).
  // Directions of the (x, y, yaw) correction whose information eigenvalue is below this
  // share of the largest keep the odometry prediction (a corridor does not fix motion
  // along it). 0 applies the whole correction.
  double degenerate_eigen_ratio = 0.05;
  double map_reference_radius_m = 5.0;  // m, map voxels this close (x/y) form the target.
  // Static occupancy probability a voxel needs to be in the map target (at least the
  // mapping's occupancy threshold). One hit from unknown gives the table's High (0.7): at
  // 0.8 a voxel must have been hit again, so the stray points one scan wrote from a
  // slightly wrong pose do not pull the next registrations towards them. With 0.5 (every
  // occupied voxel) the office tour's ATE was 0.165 m and a small-office mission's 0.113 m,
  // worse than its odometry's 0.082 m; with 0.8, 0.124 and 0.058 m (docs/RESULTS.md).
  double map_reference_min_probability = 0.8;
  // Each leaf voxel of the map target stands for the mean of the scan points that fell in
  // it (placed by their corrected poses) instead of its centre, which is up to half a voxel
  // off the surface. Registering to centres biased SLAM by several centimetres even on
  // noise-free data with ground truth for odometry; with the means (and the 0.1 m/m gate
  // above) the office tour's ATE went from 0.085 to 0.068 m (docs/RESULTS.md). false: centres.
  bool map_reference_surface_points = true;
  // The map target (voxels, k-d tree, normals) is kept between scans, as KISS-ICP keeps
  // its local map, and rebuilt once the robot is this far from where it was built (the
  // scan must stay inside it) or it is this old. Rebuilt every 0.1 s, it followed the
  // voxels each scan had just written from its own slightly wrong pose, and the pose
  // random-walked: 0.15 m ATE over a 150 s mission recording even with ground truth for
  // odometry (0.06 m with 2 s, 0.07 m with 1 s; 2 s left a short low-resolution drive with
  // too little of what came into view). A robot standing in a crowd is kept from registering to
  // people who left by the fusion below, which gives no weight to a registration while
  // odometry is certain (docs/RESULTS.md). A max age of 0 rebuilds it for every scan, as
  // the thesis's loop does (Table 5.1 in docs/RESULTS.md).
  double reference_refresh_m = 0.5;  // m.
  double reference_max_age_s = 1.0;  // s of capture time.
  // Leaf of the voxel grid thinning the scan and the map target for ICP only (the map
  // update uses every pixel); 0 registers the preprocessed scan as it is.
  double registration_voxel_m = 0.1;       // m.
  // Depth (along the optical axis) up to which a pixel goes into the registered scan and
  // the map target's surface means; 0 uses the mapping's max range. The map update always
  // uses the full range. Depth noise grows with depth squared and a return whose measured
  // depth passes the limit is dropped, so a surface just inside it looks nearer than it
  // is. Off: on the office tour 3.0, 3.4 and 3.7 m gave no consistent gain
  // (docs/RESULTS.md).
  double registration_max_depth_m = 0.0;  // m.
  // Each accepted registration is fused with the odometry prediction, per x/y and yaw, as
  // a Kalman update: the pose moves towards the registration by P / (P + R). P grows with
  // the motion since the last fusion (sigma² per metre driven, per radian turned, per
  // second for the gyro) and shrinks by each fusion; R is one registration's noise. One
  // scan's ICP is noisier than 33 ms of odometry and gyro, and a robot standing still
  // has nothing to correct: taken whole, registrations to people who had become static
  // and then left moved a still robot 0.44 m in 20 s. false takes every accepted
  // registration whole (the thesis's loop).
  bool fuse_with_odometry = true;
  double odometry_sigma_per_sqrt_m = 0.02;    // m per √m driven.
  double odometry_sigma_per_sqrt_rad = 0.01;  // rad per √rad turned.
  double heading_sigma_per_sqrt_s = 0.001;    // rad per √s (gyro noise, bias left over).
  double registration_sigma_m = 0.005;        // m, one registration's position noise.
  double registration_sigma_rad = 0.002;      // rad, its heading noise.
  // The walls' directions as a heading measurement fused after the registration
  // (WallHeading.hpp; only with fuse_with_odometry).
  WallHeadingConfig wall_heading;
  // After a pass over a recording, keyframes registered against older ones nearby close
  // the loops the pass made, and the map is built again from the corrected poses
  // (LoopClosure.hpp; dynamap map); a mission closes them when it ends and corrects its
  // trajectory (MappingWorker; or moves the pose at each one, correct_while_running).
  // Not used by SlamLoop itself.
  LoopClosureConfig loop_closure;
  std::size_t min_scan_points = 200;       // Fewer preprocessed points: no registration.
  std::size_t min_reference_points = 500;  // Fewer map voxels: the map is not yet usable.
};

// Reads a "slam:" mapping (reference, filter_dynamic, acceptance gates and a nested
// "registration:"); unknown keys are errors naming the file.
[[nodiscard]] SlamConfig ParseSlamConfig(robotio::ConfigNode& node);
// The same from a YAML file whose root holds those keys; errors name the file and key.
[[nodiscard]] robotio::Expected<SlamConfig> LoadSlamConfig(const std::string& file);

// `rig` with each Kinect's range cut as SlamLoop cuts the scans it registers: to the
// map's insertion range and to registration_max_depth_m.
[[nodiscard]] robotio::Rig RegistrationRig(robotio::Rig rig, const SlamConfig& slam,
                                           const MappingConfig& mapping);

// One scan as SlamLoop takes it before the dynamic filter, in the map frame: each frame
// (a Kinect of `rig`, seen from base at its own capture time) moved by frame_offsets[k]
// into base at the scan's time, all placed at `at_scan` and thinned to `voxel_m` on a
// grid fixed in the map.
[[nodiscard]] robotio::PointList ScanPointsInMap(const std::vector<robotio::DepthFrame>& frames,
                                                 const std::vector<robotio::Pose2D>& frame_offsets,
                                                 const robotio::Rig& rig,
                                                 const robotio::Pose2D& at_scan, double voxel_m);

// What one scan did, for reports and run statistics.
struct SlamStep {
  robotio::Pose2D predicted;  // T_map_base from odometry alone, before registration.
  robotio::Pose2D pose;       // T_map_base after the (accepted) correction.
  bool registered = false;    // A registration was attempted.
  bool accepted = false;      // Its correction was applied.
  std::string reference;      // "previous" or "map" for the one accepted (else last tried).
  RegistrationResult registration;
  bool reference_rebuilt = false;  // The map target was rebuilt for this scan.
  std::optional<double> wall_heading_rad;  // The heading the walls said, when fused.
  std::size_t scan_points = 0;  // After preprocessing.
  double preprocess_s = 0.0;    // Wall time of each stage.
  double register_s = 0.0;
  double update_s = 0.0;
};

class SlamLoop {
 public:
  SlamLoop(SlamConfig config, const MappingConfig& mapping, robotio::Rig rig);

  // One scan: frames of the rig taken at about the same time, each with the dead-reckoned
  // odometry pose at its own capture time (odometry frame, any origin). The first frame's
  // capture time is the scan's time; the others are moved to it by their odometry delta,
  // so sensor latency and robot motion between the Kinects do not smear the scan.
  SlamStep ProcessScan(const std::vector<robotio::DepthFrame>& frames,
                       const std::vector<robotio::Pose2D>& odometry_at_frames);

  [[nodiscard]] const robotio::Pose2D& pose() const { return pose_; }
  // A loop closure moved the pose: T_map_base ← correction ∘ T_map_base, and with it the
  // previous scan and the odometry prediction the next registration is checked against.
  // The map stays as written; the map target is rebuilt at the next scan.
  void ApplyCorrection(const robotio::Pose2D& correction);
  [[nodiscard]] const DualMap& map() const { return map_; }
  [[nodiscard]] const SlamConfig& config() const { return config_; }
  // The last scan's points as registered (preprocessed, thinned, base frame at its time).
  [[nodiscard]] const robotio::PointList& last_registered_scan() const { return last_scan_; }
  // The last scan's heading was measured independently of the map: the walls measured
  // within wall_heading.holds_heading_s before it (LoopClosing::Offer's heading_measured).
  [[nodiscard]] bool heading_held_by_walls() const;
  // Occupied static voxels near `around` (x/y within map_reference_radius_m, static
  // probability at least map_reference_min_probability), each as the mean of the scan
  // points seen in it (map_reference_surface_points) or as its centre, thinned to the
  // registration voxel: the map target.
  [[nodiscard]] robotio::PointList MapReference(const robotio::Pose2D& around) const;

 private:
  // Rebuilds the map target when it is too far or too old; true when it did.
  bool UpdateMapTarget(const robotio::Pose2D& predicted, std::int64_t stamp_ns);
  struct Motion {
    double driven_m = 0.0;
    double turned_rad = 0.0;
  };
  // Whether a registration is good and its `corrected` pose (degenerate directions
  // removed) within what odometry may have got wrong over `since` from `predicted`.
  [[nodiscard]] bool Acceptable(const RegistrationResult& result, const robotio::Pose2D& predicted,
                                const robotio::Pose2D& corrected, const Motion& since) const;

  SlamConfig config_;
  robotio::Rig rig_;
  robotio::Rig scan_rig_;  // rig_ with the ranges of the registered scan.
  DualMap map_;
  Registration map_registration_;                    // Target: the map around reference_centre_.
  Registration previous_registration_;               // Target: the previous scan (rebuilt per use).
  std::optional<robotio::Pose2D> reference_centre_;  // Where the map target was built.
  std::int64_t reference_stamp_ns_ = 0;              // Capture time it was built at.
  Motion map_motion_;  // Driven and turned since the last accepted map registration.
  std::optional<robotio::Pose2D> map_prediction_;  // That pose moved by odometry alone.
  robotio::Pose2D pose_;                           // T_map_base at the last scan.
  std::optional<robotio::Pose2D> last_odometry_;   // Odometry pose at the last scan.
  std::int64_t last_stamp_ns_ = -1;                // Capture time of the last scan.
  double position_variance_ = 0.0;                 // m², per axis, of pose_ (fusion).
  double heading_variance_ = 0.0;                  // rad², of pose_.
  // `registered` fused with `predicted` by the variances; shrinks them.
  [[nodiscard]] robotio::Pose2D Fuse(const robotio::Pose2D& predicted,
                                     const robotio::Pose2D& registered);
  // Fuses the heading the walls of the scan (base frame) say into `pose`; returns it.
  // Only with wall_heading_.
  std::optional<double> FuseWallHeading(const robotio::PointList& scan_base,
                                        robotio::Pose2D* pose);
  std::optional<WallHeading> wall_heading_;        // When config_.wall_heading.enabled.
  std::optional<std::int64_t> last_wall_stamp_ns_;  // Capture time the walls last measured.
  robotio::PointList previous_scan_map_;           // Last scan's points in the map frame.
  robotio::PointList last_scan_;                   // The same in the base frame.
  // Running mean of the scan points that fell in each leaf voxel (map frame).
  struct SurfaceSample {
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    float count = 0.0f;
  };
  // Adds the scan's points (map frame, corrected) to the voxels' running means.
  void AddSurfaceSamples(const robotio::PointList& scan_map);
  std::unordered_map<octomap::OcTreeKey, SurfaceSample, octomap::OcTreeKey::KeyHash>
      surface_samples_;
};

// Frames (sorted by capture stamp) grouped into scans of one instant: a group ends when a
// sensor repeats or the span from its first frame would exceed `max_span_ns`.
[[nodiscard]] std::vector<std::vector<std::size_t>> GroupIntoScans(
    const std::vector<std::int64_t>& capture_stamps_ns, const std::vector<int>& sensor_ids,
    std::int64_t max_span_ns);

}  // namespace dynamap::mapping
