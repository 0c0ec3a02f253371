// The simulator behind robotio's hardware interfaces (STYLE rule 7): one SimulatedRobot
// owns the Simulator and hands out a drive base, an IMU and one camera per Kinect that
// may be used from different threads. Time runs either as fast as the consumers pull
// (playback-like, deterministic) or paced to the wall clock (live-like).
#pragma once

#include <chrono>
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

#include "dynamap/robotio/Devices.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"

namespace dynamap::robotio::sim {

class SimulatedRobot {
 public:
  // real_time: simulated time follows the wall clock; otherwise a camera's Grab advances
  // the simulation until that camera's next frame is delivered.
  SimulatedRobot(std::unique_ptr<Simulator> simulator, bool real_time);

  [[nodiscard]] std::unique_ptr<DepthCameraInterface> Camera(int sensor_id);
  [[nodiscard]] std::unique_ptr<DriveBaseInterface> DriveBase();
  [[nodiscard]] std::unique_ptr<ImuInterface> Imu();

  // Ground truth and collisions gathered so far (taken out of the buffers).
  [[nodiscard]] std::vector<StampedPose> TakeGroundTruth();
  [[nodiscard]] std::vector<CollisionEvent> TakeCollisions();
  [[nodiscard]] std::vector<LabelFrame> TakeLabels();
  [[nodiscard]] std::int64_t now_ns();

  // Used by the adapters.
  [[nodiscard]] std::optional<DepthFrame> GrabFrame(int sensor_id, std::chrono::milliseconds timeout);
  void Command(const VelocityCommand& command);
  [[nodiscard]] std::vector<OdometryReading> TakeOdometry();
  [[nodiscard]] std::vector<ImuReading> TakeImu();

 private:
  // Advances to `t_ns` and sorts the outputs into the buffers (mutex held).
  void AdvanceLocked(std::int64_t t_ns);
  // Simulated time the wall clock has reached (real-time mode).
  [[nodiscard]] std::int64_t WallTimeNs() const;

  std::mutex mutex_;
  std::unique_ptr<Simulator> simulator_;
  bool real_time_;
  std::chrono::steady_clock::time_point wall_start_;
  std::vector<std::deque<DepthFrame>> frames_;
  std::vector<LabelFrame> labels_;
  std::vector<OdometryReading> odometry_;
  std::vector<ImuReading> imu_;
  std::vector<StampedPose> ground_truth_;
  std::vector<CollisionEvent> collisions_;
};

}  // namespace dynamap::robotio::sim
