// The guided calibration session (thesis ch. 8): a state machine floor → turn → straight →
// arcs → solve → review → save that collects floor fits and ICP motion pairs from the
// live streams, tells the operator what to do next and how complete each step is, and
// runs the solver. The CLI and the GUI drive the same object.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "dynamap/calibration/CaptureData.hpp"
#include "dynamap/calibration/FloorPlane.hpp"
#include "dynamap/calibration/RigSolver.hpp"
#include "dynamap/calibration/SensorMotion.hpp"
#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/Readings.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::calibration {

enum class SessionStep { kFloor, kTurn, kStraight, kArcs, kSolve, kReview, kSave, kDone };
[[nodiscard]] const char* SessionStepName(SessionStep step);

struct SessionConfig {
  PlaneFitConfig plane;                   // Floor fit per frame.
  IcpConfig icp;                          // Sensor motion per pair.
  SolverConfig solver;                    // Joint refinement and observability rules.
  double track_width_m = 0.54;            // m, wheel contact distance of the base.
  int floor_frames = 15;                  // Floor fits per Kinect that complete the floor step.
  double min_floor_inlier_share = 0.15;   // Fits whose floor covers less are not counted.
  int floor_pixel_stride = 4;             // px, depth subsampling for the floor fit.
  double turn_target_deg = 270.0;         // deg of turning in place, each way.
  double straight_target_m = 2.0;         // m of straight driving, each way (fwd and back).
  double arc_target_m = 2.0;              // m of arc driving, each way (left and right).
  int min_pairs_per_step = 8;             // Accepted ICP pairs per Kinect per motion step.
  // s between keyframes; every Kinect keyframes on the same time grid so their pairs
  // cover nearly the same intervals (the cross-check compares them).
  double keyframe_interval_s = 0.5;
  // Each keyframe is also paired with the one this many keyframes back: a longer baseline
  // pins yaw better (its error falls with the distance driven within a pair).
  int long_baseline_keyframes = 3;
  double still_speed_mps = 0.003;         // m/s, below it the base counts as standing still.
  double still_yaw_rate_radps = 0.02;     // rad/s (after bias), likewise for turning.
  double straight_max_curvature = 0.05;   // 1/m, motion straighter than this is "straight".
};

// Everything the operator (or a GUI) needs to show for the current step.
struct SessionProgress {
  SessionStep step = SessionStep::kFloor;
  std::string instruction;        // What to do next, one sentence.
  std::string detail;             // Counters behind `fraction`.
  double fraction = 0.0;          // 0..1 completeness of the current step.
  bool complete = false;          // Advance() allowed.
  std::vector<int> floor_fits;    // Per Kinect, accepted floor fits.
  std::vector<int> step_pairs;    // Per Kinect, accepted ICP pairs in the current step.
  std::vector<int> rejected_pairs;  // Per Kinect, ICP pairs without enough structure/fit.
  double turned_left_deg = 0.0;   // Turning in place during the turn step.
  double turned_right_deg = 0.0;
  double forward_m = 0.0;         // Straight driving during the straight step.
  double backward_m = 0.0;
  double arc_left_m = 0.0;        // Arc driving during the arcs step.
  double arc_right_m = 0.0;
  // In review: the capture step whose data the first uncalibrated parameter needs
  // (straight for yaw and wheel scales, turn for x/y and latency, floor for roll, pitch
  // and height), if any.
  std::optional<SessionStep> redo;
};

class CalibrationSession {
 public:
  CalibrationSession(robotio::Rig guess, SessionConfig config);

  // Streams, in time order (odometry/gyro stamps and frames' received stamps).
  void AddOdometry(const robotio::OdometryReading& reading);
  void AddImu(const robotio::ImuReading& reading);
  void AddDepth(const robotio::DepthFrame& frame);

  [[nodiscard]] SessionStep step() const { return step_; }
  [[nodiscard]] SessionProgress Progress() const;
  // Next step when the current one is complete; otherwise an Error saying what is missing.
  [[nodiscard]] robotio::Status Advance();
  // Leaves a capture step incomplete (the solver's observability verdicts will say so).
  void Skip();
  // From any capture step or kSolve: runs the solver and goes to kReview.
  const SolverResult& Solve();
  // From kReview: back to a capture step to add more data (data so far is kept; the
  // step's targets count afresh).
  void Redo(SessionStep capture_step);
  // From kReview/kSave: writes the calibrated rig atomically and ends the session. Refused
  // while any parameter is not calibrated unless `allow_uncalibrated`.
  [[nodiscard]] robotio::Status Save(const std::string& file, bool allow_uncalibrated = false);

  [[nodiscard]] const std::optional<SolverResult>& result() const { return result_; }
  [[nodiscard]] const CaptureData& capture() const { return capture_; }
  [[nodiscard]] const robotio::Rig& guess() const { return guess_; }
  [[nodiscard]] double gyro_bias_rad_s() const;

 private:
  struct Keyframe {
    std::int64_t received_ns = 0;
    PreparedCloud cloud;
  };
  struct StepTally {
    double left_deg = 0, right_deg = 0, forward_m = 0, backward_m = 0, arc_left_m = 0,
           arc_right_m = 0;
    std::vector<int> pairs, rejected;  // Per Kinect; in the floor step, accepted floor fits.
  };
  [[nodiscard]] robotio::Pose2D DeadReckonedAt(std::int64_t stamp_ns) const;
  void AddFloorFrame(const robotio::DepthFrame& frame);
  void AddMotionFrame(const robotio::DepthFrame& frame);
  // ICP between two keyframes of one Kinect; records an accepted pair.
  void AddPair(int sensor, const Keyframe& from, const Keyframe& to);
  [[nodiscard]] std::optional<SessionStep> StepForUncalibrated() const;
  [[nodiscard]] StepTally& Tally(SessionStep step);
  [[nodiscard]] const StepTally& Tally(SessionStep step) const;

  robotio::Rig guess_;
  SessionConfig config_;
  SessionStep step_ = SessionStep::kFloor;
  CaptureData capture_;
  // Per Kinect, the last long_baseline_keyframes + 1 motion keyframes, oldest first.
  std::vector<std::vector<Keyframe>> keyframes_;
  std::vector<std::int64_t> next_keyframe_ns_;  // Per Kinect, next grid slot.
  StepTally tallies_[4];                            // Per capture step.
  std::vector<std::pair<std::int64_t, robotio::Pose2D>> dead_reckoning_;
  double heading_ = 0.0;            // rad, integrated gyro (bias removed).
  double heading_at_odometry_ = 0.0;
  bool still_ = true;               // The last odometry increment showed no motion.
  double bias_sum_ = 0.0;
  int bias_count_ = 0;
  double pending_bias_sum_ = 0.0;  // Gyro since the last odometry reading.
  int pending_bias_count_ = 0;
  std::optional<SolverResult> result_;
};

}  // namespace dynamap::calibration
