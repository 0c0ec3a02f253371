// Settings of one autonomous exploration mission (dynamap explore, the GUI's Mission
// workspace): which world, rig and robot, how fast, how the pose is estimated, where the
// results go.
#pragma once

#include <cstdint>
#include <string>

#include "dynamap/mapping/MappingConfig.hpp"
#include "dynamap/mapping/SlamLoop.hpp"
#include "dynamap/planning/PlanningConfig.hpp"

namespace dynamap::app::runtime {

enum class PoseSource { kSlam, kOdometry, kGroundTruth };

struct MissionConfig {
  std::string world_file;            // Simulated world (resources/worlds/*.yaml); empty
                                     // on the real robot.
  // A recording to replay through the mission instead of simulating world_file
  // (MissionRuntime::CreateFromRecording); empty = simulate.
  std::string recording_dir;
  std::string rig_file;              // Kinect rig; empty = resources/rigs/two_kinects.yaml
                                     // (a replay: the recorded rig).
  std::string robot_file;            // Empty = resources/robots/segway_rmp50.yaml.
  std::string out_dir;               // Results folder (created).
  std::uint64_t seed = 1;            // Simulator seed.
  double max_time_s = 1200.0;        // s of simulated time before the mission is ended.
  // Simulated seconds per wall second; 0 = as fast as the machine allows without dropping
  // frames (the simulator waits for SLAM, like playback mode).
  double speed = 0.0;
  int kinect_width = 320;            // px; the rig's intrinsics are scaled to it.
  int kinect_height = 240;           // px.
  PoseSource poses = PoseSource::kSlam;
  bool record = false;               // Also write the recording format to out_dir/recording.
  double save_period_s = 30.0;       // s of simulated time between periodic map saves.
  double control_rate_hz = 20.0;     // Hz of simulated time, collision guard + path follower.
  double known_floor_radius_m = 0.8; // m around visited poses where unseen floor counts as
                                     // navigable (the Kinects cannot see it that close).
  // On the real robot (no world file): side of the square area around the start that the
  // 2D map covers.
  double area_m = 40.0;
  mapping::MappingConfig mapping;
  mapping::SlamConfig slam;
  planning::PlanningConfig planning;
};

[[nodiscard]] const char* ToString(PoseSource source);

}  // namespace dynamap::app::runtime
