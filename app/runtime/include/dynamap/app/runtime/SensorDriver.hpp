// The mission's sensor thread (thesis 2.2, "Sensory Grabber"), behind one interface for
// the simulator (SimulationDriver) and the real robot (DeviceDriver): it feeds the
// mediator with odometry, gyro and depth frames, applies the newest velocity command and
// advances the mission clock until the mission stops or its time is up.
#pragma once

#include <optional>
#include <string>

namespace dynamap::app::runtime {

class SensorDriver {
 public:
  virtual ~SensorDriver() = default;
  // Thread body: runs until the mission stops, its time is up or a device fails; the
  // base is told to stop before it returns.
  virtual void Run() = 0;
  [[nodiscard]] virtual bool reached_time_limit() const = 0;
  [[nodiscard]] virtual int recording_errors() const = 0;
  // The device failure that ended the run (names the device); nullopt otherwise.
  [[nodiscard]] virtual std::optional<std::string> device_error() const { return std::nullopt; }
};

}  // namespace dynamap::app::runtime
