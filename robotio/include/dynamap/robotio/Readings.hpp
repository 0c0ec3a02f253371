// Proprioceptive readings and commands of the drive base and the gyro (thesis 5.1).
#pragma once

#include <cstdint>

namespace dynamap::robotio {

// Cumulative travelled distance of each wheel as the encoders report it, already
// converted with the nominal ticks-per-metre (real scale errors remain in it).
struct OdometryReading {
  std::int64_t stamp_ns = 0;
  double left_m = 0.0;   // m, cumulative, positive forward.
  double right_m = 0.0;  // m, cumulative, positive forward.
};

struct ImuReading {
  std::int64_t stamp_ns = 0;
  double wx = 0.0;  // rad/s about base x.
  double wy = 0.0;  // rad/s about base y.
  double wz = 0.0;  // rad/s about base z (yaw rate, the one the motion model uses).
};

struct VelocityCommand {
  std::int64_t stamp_ns = 0;
  double v = 0.0;      // m/s forward.
  double omega = 0.0;  // rad/s counter-clockwise.
};

}  // namespace dynamap::robotio
