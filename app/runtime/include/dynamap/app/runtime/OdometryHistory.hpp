// Dead-reckoned base poses of the recent past (thesis 5.2, Algorithm 3), kept by the
// sensor thread as readings arrive, so SLAM can ask for the odometry pose at a frame's
// capture instant (the Kinect latency) and control can extrapolate the SLAM pose to now.
#pragma once

#include <cstdint>
#include <deque>
#include <mutex>
#include <optional>
#include <vector>

#include "dynamap/mapping/MotionModel.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"

namespace dynamap::app::runtime {

class OdometryHistory {
 public:
  // keep_s: how much history to keep (s); older entries are dropped.
  OdometryHistory(mapping::MotionModelConfig config, double keep_s);

  // Readings since the last call, each list sorted by stamp. The gyro must be added up to
  // at least the newest odometry stamp for the heading to follow it.
  void Add(const std::vector<robotio::OdometryReading>& odometry,
           const std::vector<robotio::ImuReading>& imu);

  // T_odom_base at `stamp_ns`, interpolated; nullopt before the first reading.
  [[nodiscard]] std::optional<robotio::Pose2D> PoseAt(std::int64_t stamp_ns) const;
  [[nodiscard]] std::optional<mapping::StampedPose2D> Latest() const;
  // Total distance driven by the base centre (m).
  [[nodiscard]] double distance_m() const;
  // rad/s, the gyro bias in use (learnt while the wheels stood still).
  [[nodiscard]] double gyro_bias_rad_s() const;

 private:
  mapping::MotionModelConfig config_;
  mapping::GyroBiasEstimator bias_;
  std::int64_t keep_ns_;
  mutable std::mutex mutex_;
  std::deque<mapping::StampedPose2D> poses_;
  std::deque<robotio::ImuReading> imu_;
  std::optional<robotio::OdometryReading> last_reading_;
  double distance_m_ = 0.0;
};

}  // namespace dynamap::app::runtime
