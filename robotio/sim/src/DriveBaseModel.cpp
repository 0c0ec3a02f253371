#include "dynamap/robotio/sim/DriveBaseModel.hpp"

#include <algorithm>
#include <cmath>

#include "dynamap/robotio/sim/KinectModel.hpp"

namespace dynamap::robotio::sim {

namespace {

double Approach(double current, double target, double max_step) {
  return current + std::clamp(target - current, -max_step, max_step);
}

// Exact arc integration of a constant (v, omega) over dt.
Pose2D Integrate(const Pose2D& pose, double v, double omega, double dt) {
  const double dtheta = omega * dt;
  double dx = v * dt;
  double dy = 0.0;
  if (std::abs(dtheta) > 1e-9) {
    dx = v / omega * std::sin(dtheta);
    dy = v / omega * (1.0 - std::cos(dtheta));
  }
  return pose.Compose({dx, dy, dtheta});
}

}  // namespace

DriveBaseModel::DriveBaseModel(const RobotConfig& config, const Pose2D& start_world,
                               std::uint64_t seed)
    : config_(config), seed_(seed), pose_(start_world) {}

void DriveBaseModel::SetCommand(double v, double omega) {
  v_target_ = std::clamp(v, -config_.max_speed_mps, config_.max_speed_mps);
  omega_target_ = std::clamp(omega, -config_.max_yaw_rate_radps, config_.max_yaw_rate_radps);
}

std::pair<double, double> DriveBaseModel::NextVelocities(double dt_s) const {
  return {Approach(v_, v_target_, config_.max_accel_mps2 * dt_s),
          Approach(omega_, omega_target_, config_.max_yaw_accel_radps2 * dt_s)};
}

Pose2D DriveBaseModel::Propose(double dt_s) const {
  const auto [v, omega] = NextVelocities(dt_s);
  return Integrate(pose_, (v_ + v) / 2.0, (omega_ + omega) / 2.0, dt_s);
}

void DriveBaseModel::Move(double dt_s) {
  const auto [v, omega] = NextVelocities(dt_s);
  Advance(dt_s, v, omega);
}

void DriveBaseModel::TurnOnly(double dt_s) {
  v_ = 0.0;
  Advance(dt_s, 0.0, NextVelocities(dt_s).second);
}

void DriveBaseModel::Advance(double dt_s, double v, double omega) {
  const double v_mean = (v_ + v) / 2.0;
  const double omega_mean = (omega_ + omega) / 2.0;
  pose_ = Integrate(pose_, v_mean, omega_mean, dt_s);
  v_ = v;
  omega_ = omega;
  const double half_track = config_.track_width_m / 2.0;
  const double d_left = (v_mean - omega_mean * half_track) * dt_s;
  const double d_right = (v_mean + omega_mean * half_track) * dt_s;
  left_true_ += d_left;
  right_true_ += d_right;
  // Encoders: scale error on every increment plus slip noise growing with sqrt(distance).
  const double sigma = config_.encoder_noise_m_per_sqrt_m;
  const std::uint64_t key = HashKey(seed_, ++moves_);
  left_measured_ += d_left * (1.0 + config_.encoder_scale_error_left) +
                    sigma * std::sqrt(std::abs(d_left)) * GaussianFromKey(HashKey(key, 11));
  right_measured_ += d_right * (1.0 + config_.encoder_scale_error_right) +
                     sigma * std::sqrt(std::abs(d_right)) * GaussianFromKey(HashKey(key, 12));
}

OdometryReading DriveBaseModel::Odometry(std::int64_t stamp_ns) const {
  // Whole ticks only, converted back with the nominal ticks per metre.
  const double tpm = config_.TicksPerMetre();
  OdometryReading r;
  r.stamp_ns = stamp_ns;
  r.left_m = std::floor(left_measured_ * tpm + 0.5) / tpm;
  r.right_m = std::floor(right_measured_ * tpm + 0.5) / tpm;
  return r;
}

ImuReading DriveBaseModel::Imu(std::int64_t stamp_ns, std::uint64_t index) const {
  const std::uint64_t key = HashKey(seed_ ^ 0x1D1D1D1DULL, index);
  const double sigma = config_.gyro_noise_radps;
  ImuReading r;
  r.stamp_ns = stamp_ns;
  r.wx = sigma * GaussianFromKey(HashKey(key, 21));
  r.wy = sigma * GaussianFromKey(HashKey(key, 22));
  r.wz = omega_ + config_.gyro_bias_radps + sigma * GaussianFromKey(HashKey(key, 23));
  return r;
}

}  // namespace dynamap::robotio::sim
