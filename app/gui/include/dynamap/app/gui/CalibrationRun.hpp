// The guided rig calibration on its own thread, against the simulator or a recording:
// a simulated robot with a rig that differs from the operator's guess (the guess perturbed
// per seed, as `dynamap calibrate --world` does), or a recording of the guided sequence
// replayed in recorded time (as `dynamap calibrate --log`), feeds a
// calibration::CalibrationSession. The GUI sends requests (drive, drive this step for me,
// next, skip, solve, redo, save) that run on that thread, and copies the latest published
// state; it never waits for the simulator or the solver.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "dynamap/calibration/CalibrationSession.hpp"
#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::app::gui {

struct CalibrationSetup {
  // A recording of the guided sequence to replay instead of simulating; empty = simulate.
  std::string recording_dir;
  std::string world_file;      // Simulated room (resources/worlds/calibration_room.yaml).
  std::string rig_guess_file;  // The operator's guess (resources/rigs/two_kinects_guess.yaml).
  std::string robot_file;      // Robot (resources/robots/segway_rmp50.yaml).
  std::string out_dir;         // Residual plots go here (created).
  std::uint64_t seed = 1;      // Truth perturbation and sensor noise.
  int width = 320;             // px of the simulated depth images.
  double true_latency_s = 0.1;   // s, the simulated Kinects' latency.
  double max_angle_deg = 10.0;   // deg, largest perturbation of each mounting angle.
  double max_offset_m = 0.10;    // m, largest perturbation of each mounting offset.
  double speed = 1.0;            // Simulated (or recorded) s per wall s; 0 = as fast as
                                 // possible.
};

// What the workspace shows, copied out under a short lock.
struct CalibrationState {
  calibration::SessionProgress progress;
  double sim_time_s = 0.0;
  bool driving = false;       // A manual command other than standing still is applied.
  bool auto_driving = false;  // The scripted motion of the current step runs.
  bool solving = false;
  bool replay = false;          // The session replays a recording (no driving).
  double replay_fraction = 0.0; // Share of the recording fed so far.
  std::vector<robotio::DepthFrame> depth;                    // Newest per Kinect.
  std::vector<std::optional<calibration::PlaneFit>> floor;   // Newest floor fit per Kinect.
  std::shared_ptr<const calibration::SolverResult> result;   // After Solve().
  std::vector<std::string> plots;                            // Residual plot PNGs.
  std::string saved_file;                                    // After a successful Save().
  std::string message;        // Last refusal or error, for the operator.
  std::uint64_t message_serial = 0;  // Changes with every new message.
  int collisions = 0;
};

// Rig the simulator really has: each Kinect of `guess` with angles and offsets moved by
// up to the setup's maxima, the true latency, 10 Hz frames and `width`-pixel images.
[[nodiscard]] robotio::Rig SimulatedRigTruth(const robotio::Rig& guess,
                                             const CalibrationSetup& setup);

class CalibrationRun {
 public:
  // Loads the files and starts the thread; errors name the file.
  [[nodiscard]] static robotio::Expected<std::unique_ptr<CalibrationRun>> Create(
      const CalibrationSetup& setup);
  ~CalibrationRun();
  CalibrationRun(const CalibrationRun&) = delete;
  CalibrationRun& operator=(const CalibrationRun&) = delete;

  // Requests; each returns at once and takes effect on the run's thread.
  void Drive(double v_mps, double omega_radps);
  void DriveCurrentStep();
  void Advance();
  void Skip();
  void Solve();
  void Redo(calibration::SessionStep step);
  void Save(const std::string& file, bool allow_uncalibrated);

  [[nodiscard]] CalibrationState State() const;
  [[nodiscard]] const robotio::Rig& Guess() const { return guess_; }
  // The true rig; empty for a recording (unknown).
  [[nodiscard]] const robotio::Rig& Truth() const { return truth_; }
  [[nodiscard]] const CalibrationSetup& Setup() const { return setup_; }
  // The simulated wheels' true scale factors (true distance = scale × reported).
  [[nodiscard]] double TrueScaleLeft() const { return true_scale_left_; }
  [[nodiscard]] double TrueScaleRight() const { return true_scale_right_; }
  // m, the robot's footprint radius (for drawing the rig on it).
  [[nodiscard]] double RobotRadius() const { return robot_radius_m_; }

 private:
  struct Impl;
  CalibrationRun(CalibrationSetup setup, robotio::Rig guess, robotio::Rig truth);
  void Post(std::function<void()> request);
  void Loop();
  // One step of capture from the simulator or the recording (kStepS of time).
  void CaptureStep();

  CalibrationSetup setup_;
  robotio::Rig guess_;
  robotio::Rig truth_;
  double true_scale_left_ = 1.0;
  double true_scale_right_ = 1.0;
  double robot_radius_m_ = 0.36;
  std::unique_ptr<Impl> impl_;
  mutable std::mutex state_mutex_;
  CalibrationState state_;
  std::mutex queue_mutex_;
  std::condition_variable queue_changed_;
  std::deque<std::function<void()>> queue_;
  std::atomic<bool> quit_{false};
  std::thread thread_;
};

}  // namespace dynamap::app::gui
