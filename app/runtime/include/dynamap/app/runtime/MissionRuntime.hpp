// One autonomous exploration mission (thesis 2.2): the mediator and its four threads —
// sensors (the simulator or the real robot's devices), SLAM + mapping, planning, control.
// Start, pause, resume, stop; snapshots for front ends at any time; on the end, every
// result saved.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "dynamap/app/runtime/CpuTime.hpp"
#include "dynamap/app/runtime/DeviceDriver.hpp"
#include "dynamap/app/runtime/MissionEvaluation.hpp"
#include "dynamap/app/runtime/MissionConfig.hpp"
#include "dynamap/app/runtime/MissionSnapshot.hpp"
#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"
#include "dynamap/robotio/sim/World.hpp"

namespace dynamap::app::runtime {

class Mediator;
class SensorDriver;
class MappingWorker;
class PlanningWorker;
class ControlWorker;

class MissionRuntime {
 public:
  // Loads world, rig and robot files; errors name the file and key, before anything runs.
  // With config.recording_dir set, the same as CreateFromRecording.
  [[nodiscard]] static robotio::Expected<std::unique_ptr<MissionRuntime>> Create(
      MissionConfig config);
  // The same on the real robot: `sources` are opened devices (borrowed; they must outlive
  // the runtime). No world file; the mission runs in real time (speed 1), poses from SLAM
  // or odometry, and the base moves only while the dead-man switch is held.
  [[nodiscard]] static robotio::Expected<std::unique_ptr<MissionRuntime>> CreateOnDevices(
      MissionConfig config, DeviceSources sources);
  // A recording replayed through the mission (mapping, planning and the guard run; the
  // robot cannot be steered), in recorded time: as fast as the workers go (speed 0) or
  // paced, dropping what they cannot take. Its rig, with `config.rig_file`'s extrinsics
  // when given; its world (for scoring) when it was simulated; it needs odometry (or
  // ground truth with poses from ground truth). max_time_s becomes its duration.
  [[nodiscard]] static robotio::Expected<std::unique_ptr<MissionRuntime>> CreateFromRecording(
      MissionConfig config, const std::string& recording_dir);
  ~MissionRuntime();
  MissionRuntime(const MissionRuntime&) = delete;
  MissionRuntime& operator=(const MissionRuntime&) = delete;

  void Start();
  bool Pause();
  bool Resume();
  void Stop();
  // Blocks until the mission ends (exploration complete, time limit or Stop()), then joins
  // the threads. Returns at once when it has already ended.
  void Wait();
  [[nodiscard]] bool finished() const;

  // A consistent copy of what the workers published last; never blocks them for long.
  [[nodiscard]] MissionSnapshot Snapshot() const;

  // The 3D map for a front end, without stalling the workers: RequestMapCopy() asks the
  // mapping worker for a copy after its next batch; LatestMapCopy() is the newest one made
  // (null before the first) with a version that grows with each copy.
  void RequestMapCopy();
  [[nodiscard]] std::pair<std::shared_ptr<const mapping::DualOcTree>, std::uint64_t>
  LatestMapCopy() const;

  // After Wait(): scores the run and writes every result file into the output folder.
  [[nodiscard]] robotio::Expected<MissionReport> Finish();

  [[nodiscard]] const MissionConfig& config() const { return config_; }
  // The simulated world; null on the real robot.
  [[nodiscard]] const robotio::sim::World* world() const { return world_ ? &*world_ : nullptr; }
  // The device failure that ended a mission on the robot; nullopt otherwise.
  [[nodiscard]] std::optional<std::string> device_error() const;

 private:
  MissionRuntime(MissionConfig config, std::optional<robotio::sim::World> world);
  // Rig, robot and settings checked, mediator and recording made; no driver or workers.
  // `recorded_rig`: the rig of a recording, used as it is (config.rig_file is not read).
  [[nodiscard]] static robotio::Expected<std::unique_ptr<MissionRuntime>> Prepare(
      MissionConfig config, std::optional<robotio::sim::World> world,
      std::optional<robotio::Rig> recorded_rig);
  void MakeWorkers(const planning::GridMap& area);
  void Monitor();

  MissionConfig config_;
  std::optional<robotio::sim::World> world_;
  robotio::Rig rig_;
  robotio::sim::RobotConfig robot_;
  double footprint_radius_m_ = 0.36;
  std::unique_ptr<Mediator> mediator_;
  std::unique_ptr<robotio::RecordingWriter> recording_;
  std::unique_ptr<robotio::RecordingReader> reader_;  // The recording a replay reads.
  std::unique_ptr<SensorDriver> driver_;
  std::shared_ptr<const TruthGrid> live_truth_;  // Simulated truth at the time limit.
  std::unique_ptr<MappingWorker> mapping_;
  std::unique_ptr<PlanningWorker> planning_;
  std::unique_ptr<ControlWorker> control_;
  std::vector<std::thread> threads_;
  bool joined_ = false;
  std::chrono::steady_clock::time_point started_{};  // Wall clock at Start().
  double wall_time_s_ = 0.0;                          // Start() to the workers' end.
  double process_cpu_at_start_s_ = 0.0;
  MissionCpu cpu_;  // Each worker writes its share as its thread ends (read after joining).
};

}  // namespace dynamap::app::runtime
