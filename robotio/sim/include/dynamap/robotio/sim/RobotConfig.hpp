// The simulated drive base's geometry, limits and sensor errors
// (resources/robots/segway_rmp50.yaml).
#pragma once

#include <string>

#include "dynamap/robotio/Expected.hpp"

namespace dynamap::robotio::sim {

struct RobotConfig {
  std::string name = "segway_rmp50";
  double track_width_m = 0.54;        // m, distance between the wheel contact points.
  double wheel_radius_m = 0.2;        // m.
  double ticks_per_rev = 4096.0;      // Encoder ticks per wheel revolution.
  double footprint_radius_m = 0.36;   // m, circle around the base origin that must stay free.
  double height_m = 0.9;              // m, top of the robot incl. the Kinects.
  double max_speed_mps = 1.0;         // m/s, |v| limit.
  double max_yaw_rate_radps = 1.5;    // rad/s, |omega| limit.
  double max_accel_mps2 = 0.8;        // m/s^2, |dv/dt| limit.
  double max_yaw_accel_radps2 = 3.0;  // rad/s^2, |domega/dt| limit.
  double odometry_rate_hz = 50.0;     // Hz.
  double imu_rate_hz = 100.0;         // Hz.
  double encoder_scale_error_left = 0.01;    // Measured / true distance - 1, left wheel.
  double encoder_scale_error_right = -0.008;  // Same, right wheel.
  double encoder_noise_m_per_sqrt_m = 0.001;  // m per sqrt(m) travelled, random walk.
  double gyro_bias_radps = 0.003;     // rad/s, constant offset of the yaw rate.
  double gyro_noise_radps = 0.004;    // rad/s, white noise per reading (all axes).

  [[nodiscard]] double TicksPerMetre() const;
};

[[nodiscard]] Expected<RobotConfig> LoadRobotConfig(const std::string& file);

}  // namespace dynamap::robotio::sim
