#include "dynamap/robotio/sim/SimulatedDevices.hpp"

#include <thread>

#include "dynamap/robotio/Time.hpp"

namespace dynamap::robotio::sim {

namespace {

constexpr std::int64_t kFastStepNs = 10'000'000;  // Simulated time per advance while pulling.
constexpr std::size_t kMaxQueuedFrames = 8;       // Per camera; older frames are dropped like
                                                  // a driver's ring buffer.

class SimCamera : public DepthCameraInterface {
 public:
  SimCamera(SimulatedRobot* robot, int sensor) : robot_(robot), sensor_(sensor) {}
  int sensor_id() const override { return sensor_; }
  Expected<std::optional<DepthFrame>> Grab(std::chrono::milliseconds timeout) override {
    return robot_->GrabFrame(sensor_, timeout);
  }

 private:
  SimulatedRobot* robot_;
  int sensor_;
};

class SimDriveBase : public DriveBaseInterface {
 public:
  explicit SimDriveBase(SimulatedRobot* robot) : robot_(robot) {}
  Status Command(const VelocityCommand& command) override {
    robot_->Command(command);
    return Ok{};
  }
  Expected<std::vector<OdometryReading>> ReadOdometry() override { return robot_->TakeOdometry(); }
  void Stop() override { robot_->Command(VelocityCommand{}); }

 private:
  SimulatedRobot* robot_;
};

class SimImu : public ImuInterface {
 public:
  explicit SimImu(SimulatedRobot* robot) : robot_(robot) {}
  Expected<std::vector<ImuReading>> ReadImu() override { return robot_->TakeImu(); }

 private:
  SimulatedRobot* robot_;
};

template <typename T>
std::vector<T> Take(std::vector<T>* buffer) {
  std::vector<T> out;
  out.swap(*buffer);
  return out;
}

}  // namespace

SimulatedRobot::SimulatedRobot(std::unique_ptr<Simulator> simulator, bool real_time)
    : simulator_(std::move(simulator)),
      real_time_(real_time),
      wall_start_(std::chrono::steady_clock::now()),
      frames_(simulator_->rig().kinects.size()) {}

std::unique_ptr<DepthCameraInterface> SimulatedRobot::Camera(int sensor_id) {
  return std::make_unique<SimCamera>(this, sensor_id);
}
std::unique_ptr<DriveBaseInterface> SimulatedRobot::DriveBase() {
  return std::make_unique<SimDriveBase>(this);
}
std::unique_ptr<ImuInterface> SimulatedRobot::Imu() { return std::make_unique<SimImu>(this); }

std::int64_t SimulatedRobot::WallTimeNs() const {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() -
                                                              wall_start_)
      .count();
}

void SimulatedRobot::AdvanceLocked(std::int64_t t_ns) {
  SimOutput out = simulator_->AdvanceTo(t_ns);
  for (SimFrame& f : out.frames) {
    auto& queue = frames_[f.depth.sensor_id];
    queue.push_back(std::move(f.depth));
    if (queue.size() > kMaxQueuedFrames) queue.pop_front();
    labels_.push_back(std::move(f.labels));
  }
  odometry_.insert(odometry_.end(), out.odometry.begin(), out.odometry.end());
  imu_.insert(imu_.end(), out.imu.begin(), out.imu.end());
  ground_truth_.insert(ground_truth_.end(), out.ground_truth.begin(), out.ground_truth.end());
  collisions_.insert(collisions_.end(), out.collisions.begin(), out.collisions.end());
}

std::optional<DepthFrame> SimulatedRobot::GrabFrame(int sensor_id,
                                                    std::chrono::milliseconds timeout) {
  if (sensor_id < 0 || sensor_id >= static_cast<int>(frames_.size())) return std::nullopt;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (real_time_) {
        AdvanceLocked(WallTimeNs());
      } else if (frames_[sensor_id].empty()) {
        // Pull mode: run on until this camera has a frame (bounded by one frame period).
        const std::int64_t limit = simulator_->now_ns() + SecondsToNanos(1.0);
        while (frames_[sensor_id].empty() && simulator_->now_ns() < limit) {
          AdvanceLocked(simulator_->now_ns() + kFastStepNs);
        }
      }
      if (!frames_[sensor_id].empty()) {
        DepthFrame frame = std::move(frames_[sensor_id].front());
        frames_[sensor_id].pop_front();
        return frame;
      }
    }
    if (std::chrono::steady_clock::now() >= deadline) return std::nullopt;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

void SimulatedRobot::Command(const VelocityCommand& command) {
  std::lock_guard<std::mutex> lock(mutex_);
  simulator_->SetCommand(command);
}

std::vector<OdometryReading> SimulatedRobot::TakeOdometry() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (real_time_) AdvanceLocked(WallTimeNs());
  return Take(&odometry_);
}

std::vector<ImuReading> SimulatedRobot::TakeImu() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (real_time_) AdvanceLocked(WallTimeNs());
  return Take(&imu_);
}

std::vector<StampedPose> SimulatedRobot::TakeGroundTruth() {
  std::lock_guard<std::mutex> lock(mutex_);
  return Take(&ground_truth_);
}

std::vector<CollisionEvent> SimulatedRobot::TakeCollisions() {
  std::lock_guard<std::mutex> lock(mutex_);
  return Take(&collisions_);
}

std::vector<LabelFrame> SimulatedRobot::TakeLabels() {
  std::lock_guard<std::mutex> lock(mutex_);
  return Take(&labels_);
}

std::int64_t SimulatedRobot::now_ns() {
  std::lock_guard<std::mutex> lock(mutex_);
  return simulator_->now_ns();
}

}  // namespace dynamap::robotio::sim
