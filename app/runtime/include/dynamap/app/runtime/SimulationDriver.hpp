// The sensor thread of a simulated mission (thesis 2.2, "Sensory Grabber"): steps the
// simulator, applies the newest velocity command, hands frames, odometry and gyro to the
// mediator, and writes the recording. Paced to the mission clock, or, at speed 0, in
// lockstep with the workers so nothing is dropped and the run is as fast as they are.
#pragma once

#include <memory>

#include "dynamap/app/runtime/Mediator.hpp"
#include "dynamap/app/runtime/SensorDriver.hpp"
#include "dynamap/robotio/RecordingWriter.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"

namespace dynamap::app::runtime {

struct SimulationDriverConfig {
  double step_s = 0.01;           // s of simulated time per step.
  double max_time_s = 1200.0;     // s, the mission ends here.
  double control_period_s = 0.05; // s, lockstep: control must have run this recently.
  double replan_period_s = 0.5;   // s, lockstep: planning must have run this recently.
};

class SimulationDriver final : public SensorDriver {
 public:
  SimulationDriver(std::unique_ptr<robotio::sim::Simulator> simulator, Mediator& mediator,
                   SimulationDriverConfig config, robotio::RecordingWriter* recording);

  // Thread body: runs until the mission stops or reaches max_time_s.
  void Run() override;

  [[nodiscard]] const robotio::sim::Simulator& simulator() const { return *simulator_; }
  [[nodiscard]] bool reached_time_limit() const override { return reached_time_limit_; }
  [[nodiscard]] int recording_errors() const override { return recording_errors_; }

 private:
  void Publish(robotio::sim::SimOutput& out);

  std::unique_ptr<robotio::sim::Simulator> simulator_;
  Mediator& mediator_;
  SimulationDriverConfig config_;
  robotio::RecordingWriter* recording_;
  bool reached_time_limit_ = false;
  int recording_errors_ = 0;
};

}  // namespace dynamap::app::runtime
