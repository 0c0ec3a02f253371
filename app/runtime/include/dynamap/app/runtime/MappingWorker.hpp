// The SLAM thread of the mission runtime (thesis Algorithm 4): takes the newest depth
// frames, localises them, inserts them into the dual map, re-projects the 2D grid where
// the frames looked, and publishes pose and grid through the mediator. It also gathers
// what the mission report scores: labelled points (static/dynamic accuracy) and the
// surfaces seen from within the inspection distance. With SLAM poses and loop closure on
// (slam.loop_closure), keyframes are kept as the robot goes; CloseLoops() at the end
// registers each against older ones nearby and corrects the trajectory (or, with
// correct_while_running, each closure moves the pose as soon as it is found).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "dynamap/app/runtime/InspectedSurfaces.hpp"
#include "dynamap/app/runtime/Mediator.hpp"
#include "dynamap/app/runtime/MissionConfig.hpp"
#include "dynamap/app/runtime/ScanAssembler.hpp"
#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/mapping/LoopClosure.hpp"
#include "dynamap/mapping/MapEvaluation.hpp"
#include "dynamap/mapping/SlamLoop.hpp"
#include "dynamap/planning/MapProjection.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::app::runtime {

struct MappingWorkerConfig {
  PoseSource poses = PoseSource::kSlam;
  mapping::MappingConfig mapping;
  mapping::SlamConfig slam;
  planning::ProjectionConfig projection;
  planning::GridMap area;             // Geometry of the projected grid (cells unknown).
  std::string save_file;              // Map saved here periodically (atomically); "" = never.
  double save_period_s = 30.0;        // s of simulated time.
  double inspection_distance_m = 2.5; // m, surfaces hit from closer count as inspected.
  int evaluation_stride = 8;          // px, pixel step of the labelled-point evaluation.
};

class MappingWorker {
 public:
  MappingWorker(Mediator& mediator, robotio::Rig rig, MappingWorkerConfig config);
  ~MappingWorker();

  // Thread body: until the mission stops.
  void Run();

  // After Run() returned.
  [[nodiscard]] const mapping::DualMap& map() const { return slam_ ? slam_->map() : map_; }
  [[nodiscard]] mapping::PointAccuracy Accuracy() const;
  [[nodiscard]] mapping::MisclassifiedVoxels Misclassified() const;
  // A surface point (frame of the simulator's true poses) hit within the inspection
  // distance, within one voxel (InspectedSurfaces).
  [[nodiscard]] bool Inspected(const Eigen::Vector3f& p) const;
  [[nodiscard]] const planning::GridMap& grid() const { return projector_.map(); }
  // After Run() returned: the closures not yet made (all of them, unless they were made
  // as the robot went) and the pose graph solved over the whole mission.
  void CloseLoops();
  // The estimates moved by every loop closure made (each by the keyframes around it), the
  // best trajectory the mission knows at its end; `estimates` unchanged without closures.
  [[nodiscard]] robotio::Trajectory Corrected(const robotio::Trajectory& estimates) const;
  // What loop closure did; none when it is off or poses do not come from SLAM.
  [[nodiscard]] const mapping::LoopClosureSummary* loop_closure() const {
    return loop_closing_ ? &loop_closure_ : nullptr;
  }
  [[nodiscard]] double median_insert_ms() const;
  [[nodiscard]] double p95_insert_ms() const;

 private:
  // One batch of frames (newest per Kinect): placed by SLAM as one scan, or each by
  // odometry / ground truth, then inserted and scored.
  void Process(const std::vector<CapturedFrame>& frames);
  void Score(const CapturedFrame& frame, const robotio::KinectMount& mount,
             const robotio::Pose2D& T_map_base, const robotio::Pose2D& odometry);
  // Re-projects the grid columns the processed frames looked through, then publishes it.
  void Reproject();

  Mediator& mediator_;
  robotio::Rig rig_;
  MappingWorkerConfig config_;
  mapping::DualMap map_;                  // Used when poses come from odometry / truth.
  std::optional<mapping::SlamLoop> slam_;  // Owns the map when poses come from SLAM.
  std::optional<mapping::LoopClosing> loop_closing_;  // With SLAM, when enabled.
  mapping::LoopClosureSummary loop_closure_;  // Once CloseLoops() ran.
  bool loops_closed_ = false;
  planning::MapProjector projector_;
  mapping::PointAccuracyCounter accuracy_;
  InspectedSurfaces inspected_;
  ScanAssembler scans_;                   // Both Kinects' frames of one instant together.
  std::vector<Eigen::Vector2f> touched_;  // Columns to re-project after this batch.
  std::vector<Eigen::Vector2f> hit_;      // Columns where this batch hit an obstacle.
  std::vector<double> insert_ms_;
  std::int64_t last_save_ns_ = 0;
};

}  // namespace dynamap::app::runtime
