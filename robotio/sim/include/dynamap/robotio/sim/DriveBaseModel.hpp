// Differential-drive kinematics of the Segway RMP50 with velocity and acceleration
// limits, wheel encoders with per-wheel scale error and noise, and a biased noisy gyro.
#pragma once

#include <cstdint>

#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"

namespace dynamap::robotio::sim {

class DriveBaseModel {
 public:
  DriveBaseModel(const RobotConfig& config, const Pose2D& start_world, std::uint64_t seed);

  // Target velocities; clamped to the limits.
  void SetCommand(double v, double omega);
  // The pose the base would reach after dt (acceleration limits applied), without moving.
  [[nodiscard]] Pose2D Propose(double dt_s) const;
  // Accepts the proposed motion over dt (wheels turn, encoders count).
  void Move(double dt_s);
  // The base is blocked ahead but turns: its forward velocity drops to zero and the
  // commanded turn goes on (a circular footprint turns on the spot against a wall).
  void TurnOnly(double dt_s);

  [[nodiscard]] OdometryReading Odometry(std::int64_t stamp_ns) const;
  // One gyro reading of the current rates; `index` numbers readings for reproducible noise.
  [[nodiscard]] ImuReading Imu(std::int64_t stamp_ns, std::uint64_t index) const;

  [[nodiscard]] const Pose2D& pose_world() const { return pose_; }
  [[nodiscard]] double v() const { return v_; }
  [[nodiscard]] double omega() const { return omega_; }
  [[nodiscard]] double true_left_m() const { return left_true_; }
  [[nodiscard]] double true_right_m() const { return right_true_; }

 private:
  [[nodiscard]] std::pair<double, double> NextVelocities(double dt_s) const;
  // Moves from the current velocities to (v, omega) over dt: pose, wheels, encoders.
  void Advance(double dt_s, double v, double omega);

  RobotConfig config_;
  std::uint64_t seed_;
  Pose2D pose_;
  double v_ = 0.0;
  double omega_ = 0.0;
  double v_target_ = 0.0;
  double omega_target_ = 0.0;
  double left_true_ = 0.0;
  double right_true_ = 0.0;
  double left_measured_ = 0.0;  // Before tick quantisation.
  double right_measured_ = 0.0;
  std::uint64_t moves_ = 0;
};

}  // namespace dynamap::robotio::sim
