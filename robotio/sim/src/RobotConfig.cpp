#include "dynamap/robotio/sim/RobotConfig.hpp"

#include <cmath>

#include "dynamap/robotio/ConfigReader.hpp"

namespace dynamap::robotio::sim {

double RobotConfig::TicksPerMetre() const { return ticks_per_rev / (2.0 * M_PI * wheel_radius_m); }

Expected<RobotConfig> LoadRobotConfig(const std::string& file) {
  return ParseYamlFile<RobotConfig>(file, [](ConfigNode& n) {
    RobotConfig c;
    n.Read("name", &c.name);
    n.Read("track_width_m", &c.track_width_m, 0.1, 3.0);
    n.Read("wheel_radius_m", &c.wheel_radius_m, 0.02, 1.0);
    n.Read("ticks_per_rev", &c.ticks_per_rev, 1.0, 1e7);
    n.Read("footprint_radius_m", &c.footprint_radius_m, 0.05, 3.0);
    n.Read("height_m", &c.height_m, 0.1, 3.0);
    n.Read("max_speed_mps", &c.max_speed_mps, 0.01, 10.0);
    n.Read("max_yaw_rate_radps", &c.max_yaw_rate_radps, 0.01, 20.0);
    n.Read("max_accel_mps2", &c.max_accel_mps2, 0.01, 20.0);
    n.Read("max_yaw_accel_radps2", &c.max_yaw_accel_radps2, 0.01, 50.0);
    n.Read("odometry_rate_hz", &c.odometry_rate_hz, 1.0, 1000.0);
    n.Read("imu_rate_hz", &c.imu_rate_hz, 1.0, 1000.0);
    if (auto encoder = n.OptionalChild("encoder")) {
      encoder->Read("scale_error_left", &c.encoder_scale_error_left, -0.5, 0.5);
      encoder->Read("scale_error_right", &c.encoder_scale_error_right, -0.5, 0.5);
      encoder->Read("noise_m_per_sqrt_m", &c.encoder_noise_m_per_sqrt_m, 0.0, 0.5);
    }
    if (auto gyro = n.OptionalChild("gyro")) {
      gyro->Read("bias_radps", &c.gyro_bias_radps, -1.0, 1.0);
      gyro->Read("noise_radps", &c.gyro_noise_radps, 0.0, 1.0);
    }
    return c;
  });
}

}  // namespace dynamap::robotio::sim
