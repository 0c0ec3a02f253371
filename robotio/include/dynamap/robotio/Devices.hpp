// Hardware interfaces (STYLE rule 7): the simulator, log playback and the real drivers
// implement the same ones, so everything above robotio is unaware of which it talks to.
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Readings.hpp"

namespace dynamap::robotio {

class DepthCameraInterface {
 public:
  virtual ~DepthCameraInterface() = default;
  [[nodiscard]] virtual int sensor_id() const = 0;
  // The next frame, waiting at most `timeout`; nullopt on time-out, Error when the device
  // is gone (the message names it).
  [[nodiscard]] virtual Expected<std::optional<DepthFrame>> Grab(
      std::chrono::milliseconds timeout) = 0;
};

class DriveBaseInterface {
 public:
  virtual ~DriveBaseInterface() = default;
  // Velocity command; implementations clamp to the base's limits.
  [[nodiscard]] virtual Status Command(const VelocityCommand& command) = 0;
  // Odometry readings that arrived since the last call, oldest first.
  [[nodiscard]] virtual Expected<std::vector<OdometryReading>> ReadOdometry() = 0;
  // Brings the base to a stop (also used by watchdogs and on shutdown).
  virtual void Stop() = 0;
};

class ImuInterface {
 public:
  virtual ~ImuInterface() = default;
  // Gyro readings that arrived since the last call, oldest first.
  [[nodiscard]] virtual Expected<std::vector<ImuReading>> ReadImu() = 0;
};

}  // namespace dynamap::robotio
