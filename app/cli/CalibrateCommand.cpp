#include "cli/CalibrateCommand.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>

#include "cli/CommandSupport.hpp"
#include "cli/ProgressLine.hpp"
#include "dynamap/calibration/CalibrationSession.hpp"
#include "dynamap/calibration/CaptureReplay.hpp"
#include "dynamap/calibration/ResidualPlot.hpp"
#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app {
namespace {

namespace cal = calibration;
namespace sim = robotio::sim;
constexpr const char* kCommand = "calibrate";
constexpr double kDeg = M_PI / 180.0;

struct CalibrateOptions {
  std::string log;
  std::string world;
  std::string rig_guess;
  std::string robot;
  std::string out;
  std::uint64_t seed = 1;
  int width = 320;                  // px of the simulated depth images.
  double true_latency_s = 0.1;      // s, the simulated Kinects' latency.
  double max_angle_deg = 10.0;      // Perturbation of the simulated truth from the guess.
  double max_offset_m = 0.10;
  bool allow_uncalibrated = false;
  int max_redos = 2;                // Simulated: capture steps redone for weak parameters.
};

// What the simulator really has, for the report's error column.
struct GroundTruth {
  robotio::Rig rig;
  double scale_left = 1.0;
  double scale_right = 1.0;
  // True optical-frame pose of every delivered frame, by (Kinect, receive stamp).
  std::map<std::pair<int, std::int64_t>, Eigen::Isometry3d> sensor_poses;
};

robotio::Rig PerturbedTruth(const robotio::Rig& guess, const CalibrateOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  robotio::Rig truth = guess;
  for (robotio::KinectMount& m : truth.kinects) {
    Eigen::Vector3d rpy = robotio::MountRollPitchYaw(m.T_base_kinect);
    Eigen::Vector3d t = m.T_base_kinect.translation();
    for (int i = 0; i < 3; ++i) rpy[i] += options.max_angle_deg * kDeg * unit(rng);
    for (int i = 0; i < 3; ++i) t[i] += options.max_offset_m * unit(rng);
    m.T_base_kinect = robotio::MountPose(t, rpy);
    m.latency_s = options.true_latency_s;
    m.rate_hz = 10.0;  // Keyframes are 0.5 s apart; rendering all 30 Hz would only cost time.
    const int height = options.width * m.intrinsics.height / m.intrinsics.width;
    m.intrinsics = m.intrinsics.Scaled(options.width, height);
  }
  return truth;
}

// One scripted phase of the guided drive: a command held until `done` or the time limit.
struct Phase {
  double v = 0.0;
  double omega = 0.0;
  std::function<bool(const cal::SessionProgress&)> done;
  double max_s = 40.0;
};

void Feed(cal::CalibrationSession* session, const sim::SimOutput& out, GroundTruth* truth) {
  std::size_t i = 0, j = 0;
  while (i < out.odometry.size() || j < out.imu.size()) {
    if (j >= out.imu.size() ||
        (i < out.odometry.size() && out.odometry[i].stamp_ns <= out.imu[j].stamp_ns)) {
      session->AddOdometry(out.odometry[i++]);
    } else {
      session->AddImu(out.imu[j++]);
    }
  }
  for (const sim::SimFrame& frame : out.frames) {
    session->AddDepth(frame.depth);
    truth->sensor_poses[{frame.depth.sensor_id, frame.depth.received_ns}] =
        frame.T_map_kinect.pose;
  }
}

// The guided sequence driven in the simulator, step by step, as an operator would with
// the gamepad: each capture step's phases are held until the session counts them done.
class SimulatedDrive {
 public:
  SimulatedDrive(cal::CalibrationSession* session, const CalibrateOptions& options,
                 const sim::RobotConfig& robot, GroundTruth* truth)
      : session_(session), truth_(truth) {
    auto world = sim::LoadWorld(options.world);
    if (!world) FailCommand(kCommand, world.error().message);
    truth->rig = PerturbedTruth(session->guess(), options);
    truth->scale_left = 1.0 / (1.0 + robot.encoder_scale_error_left);
    truth->scale_right = 1.0 / (1.0 + robot.encoder_scale_error_right);
    sim::SimulatorConfig config;
    config.seed = options.seed;
    simulator_ = std::make_unique<sim::Simulator>(*world, robot, truth->rig, config);
  }

  // Drives `step` until complete (or its phases time out); `label` heads the progress line.
  void Drive(cal::SessionStep step, const std::string& label) {
    const cal::SessionConfig targets;  // CalibrationSession runs with the default targets.
    ProgressLine progress(label);
    for (const Phase& phase : Phases(step, targets)) {
      simulator_->SetCommand({simulator_->now_ns(), phase.v, phase.omega});
      for (double t = 0.0; t < phase.max_s; t += kStepS) {
        Feed(session_, simulator_->Advance(kStepS), truth_);
        const cal::SessionProgress p = session_->Progress();
        progress.Update(p.fraction, std::string(cal::SessionStepName(p.step)) + ": " + p.detail);
        if (phase.done(p)) break;
      }
    }
    simulator_->SetCommand({simulator_->now_ns(), 0.0, 0.0});
    progress.Finish(std::string(cal::SessionStepName(step)) + ": " + session_->Progress().detail);
  }

  [[nodiscard]] int collisions() const { return simulator_->collision_count(); }

 private:
  static constexpr double kStepS = 0.05;

  static std::vector<Phase> Phases(cal::SessionStep step, const cal::SessionConfig& targets) {
    const Phase pause{0.0, 0.0, [](const cal::SessionProgress&) { return false; }, 1.0};
    switch (step) {
      case cal::SessionStep::kFloor:
        return {{0.0, 0.0, [](const cal::SessionProgress& p) { return p.complete; }, 15.0}};
      case cal::SessionStep::kTurn:
        return {{0.0, 0.5, [=](const cal::SessionProgress& p) { return p.turned_left_deg >= targets.turn_target_deg; }},
                pause,
                {0.0, -0.5, [=](const cal::SessionProgress& p) { return p.turned_right_deg >= targets.turn_target_deg; }},
                pause};
      case cal::SessionStep::kStraight:
        return {{0.3, 0.0, [=](const cal::SessionProgress& p) { return p.forward_m >= targets.straight_target_m; }},
                pause,
                {-0.3, 0.0, [=](const cal::SessionProgress& p) { return p.backward_m >= targets.straight_target_m; }},
                pause};
      case cal::SessionStep::kArcs:
        return {{0.3, 0.4, [=](const cal::SessionProgress& p) { return p.arc_left_m >= targets.arc_target_m; }},
                pause,
                {-0.3, -0.4, [=](const cal::SessionProgress& p) { return p.arc_right_m >= targets.arc_target_m; }},
                pause};
      default:
        return {};
    }
  }

  cal::CalibrationSession* session_;
  GroundTruth* truth_;
  std::unique_ptr<sim::Simulator> simulator_;
};

// Drives floor → turn → straight → arcs and solves; while the review names a capture step
// that would calibrate what is still weak, redoes it (at most `max_redos` times) and solves
// again. Returns the steps redone, in order.
std::vector<std::string> CalibrateInSimulator(cal::CalibrationSession* session,
                                              const CalibrateOptions& options,
                                              const sim::RobotConfig& robot,
                                              GroundTruth* truth) {
  SimulatedDrive drive(session, options, robot, truth);
  for (const cal::SessionStep step : {cal::SessionStep::kFloor, cal::SessionStep::kTurn,
                                      cal::SessionStep::kStraight, cal::SessionStep::kArcs}) {
    drive.Drive(step, "calibrating");
    if (!session->Advance().ok()) {
      std::fprintf(stderr, "dynamap calibrate: step '%s' left incomplete: %s\n",
                   cal::SessionStepName(session->step()), session->Progress().detail.c_str());
      session->Skip();
    }
  }
  session->Solve();
  std::vector<std::string> redone;
  for (int round = 0; round < options.max_redos; ++round) {
    const std::optional<cal::SessionStep> redo = session->Progress().redo;
    if (!redo) break;
    session->Redo(*redo);
    drive.Drive(*redo, "redoing");
    redone.push_back(cal::SessionStepName(*redo));
    session->Solve();
  }
  std::fprintf(stderr, "dynamap calibrate: capture done, collisions: %d\n", drive.collisions());
  return redone;
}

void ReplayRecording(cal::CalibrationSession* session, const std::string& dir) {
  auto reader = robotio::RecordingReader::Open(dir);
  if (!reader) FailCommand(kCommand, reader.error().message);
  cal::CaptureReplay replay(*reader);
  ProgressLine progress("replaying");
  constexpr std::int64_t kChunkNs = 100'000'000;  // 0.1 s of recorded time per update.
  for (std::int64_t t = reader->first_stamp_ns(); !replay.done(); t += kChunkNs) {
    if (auto fed = replay.FeedUntil(*session, t, nullptr); !fed) {
      FailCommand(kCommand, fed.error().message);
    }
    progress.Update(replay.fraction(), cal::SessionStepName(session->step()));
  }
  progress.Finish(std::to_string(reader->depth_entries().size()) + " frames");
}

nlohmann::json ParameterJson(const cal::ParameterEstimate& p, std::optional<double> truth) {
  const bool angle = p.unit == "rad";
  const double f = angle ? 1.0 / kDeg : 1.0;
  nlohmann::json j = {{"name", p.name},
                      {"unit", angle ? "deg" : p.unit},
                      {"status", cal::ObservabilityName(p.status)},
                      {"guess", p.guess * f},
                      {"initial", p.initial * f},
                      {"std_dev", p.std_dev * f}};
  // An uncalibrated value is not reported as the estimate.
  j["estimate"] = p.Calibrated() ? nlohmann::json(p.estimate * f) : nlohmann::json(nullptr);
  if (!p.Calibrated()) j["uncalibrated_value"] = p.estimate * f;
  if (!p.reason.empty()) j["reason"] = p.reason;
  if (truth) {
    double error = p.estimate - *truth;
    if (angle) error = std::remainder(error, 2.0 * M_PI);
    j["truth"] = *truth * f;
    j["error"] = error * f;
  }
  return j;
}

// How far each Kinect's ICP motions are from the simulator's true sensor motions: RMS and
// mean (a bias the solver cannot average away) of the rotation and translation errors.
nlohmann::json SensorMotionErrors(const cal::KinectCapture& kinect, int sensor,
                                  const GroundTruth& truth) {
  Eigen::Vector3d rot_sum = Eigen::Vector3d::Zero(), trans_sum = Eigen::Vector3d::Zero();
  double rot_sq = 0.0, trans_sq = 0.0;
  int n = 0;
  for (const cal::MotionPair& pair : kinect.motions) {
    const auto from = truth.sensor_poses.find({sensor, pair.from_received_ns});
    const auto to = truth.sensor_poses.find({sensor, pair.to_received_ns});
    if (from == truth.sensor_poses.end() || to == truth.sensor_poses.end()) continue;
    const Eigen::Isometry3d true_motion = from->second.inverse() * to->second;
    const Eigen::Isometry3d error = true_motion.inverse() * pair.T_from_to;
    const Eigen::AngleAxisd angle_axis(error.linear());
    const Eigen::Vector3d rotation = angle_axis.axis() * angle_axis.angle() / kDeg;
    rot_sum += rotation;
    trans_sum += error.translation();
    rot_sq += rotation.squaredNorm();
    trans_sq += error.translation().squaredNorm();
    ++n;
  }
  if (n == 0) return {{"pairs", 0}};
  auto vec = [](const Eigen::Vector3d& v) { return std::vector<double>{v.x(), v.y(), v.z()}; };
  return {{"pairs", n},
          {"rotation_rms_deg", std::sqrt(rot_sq / n)},
          {"rotation_mean_deg", vec(rot_sum / n)},
          {"translation_rms_m", std::sqrt(trans_sq / n)},
          {"translation_mean_m", vec(trans_sum / n)}};
}

void Run(const CalibrateOptions& options) {
  if (options.log.empty() == options.world.empty()) {
    FailCommand(kCommand, "give exactly one of --log DIR and --world FILE");
  }
  auto guess = robotio::LoadRig(options.rig_guess);
  if (!guess) FailCommand(kCommand, guess.error().message);
  const std::filesystem::path out_dir =
      std::filesystem::absolute(options.out).parent_path();
  std::error_code ec;
  std::filesystem::create_directories(out_dir, ec);
  if (ec) FailCommand(kCommand, out_dir.string() + ": cannot create folder (" + ec.message() + ")");

  cal::SessionConfig config;
  std::optional<GroundTruth> truth;
  std::optional<sim::RobotConfig> robot;
  if (!options.world.empty()) {
    auto loaded = sim::LoadRobotConfig(options.robot.empty()
                                           ? ResourcePath("robots/segway_rmp50.yaml")
                                           : options.robot);
    if (!loaded) FailCommand(kCommand, loaded.error().message);
    robot = *loaded;
    config.track_width_m = robot->track_width_m;
  }
  cal::CalibrationSession session(*guess, config);
  std::vector<std::string> redone;
  if (robot) {
    truth.emplace();
    redone = CalibrateInSimulator(&session, options, *robot, &*truth);
  } else {
    ReplayRecording(&session, options.log);
    session.Solve();
  }
  const cal::SolverResult& result = *session.result();

  nlohmann::json parameters = nlohmann::json::array();
  nlohmann::json kinects = nlohmann::json::array();
  for (std::size_t k = 0; k < result.kinects.size(); ++k) {
    const cal::KinectEstimate& e = result.kinects[k];
    std::optional<Eigen::Vector3d> rpy, t;
    if (truth) {
      rpy = robotio::MountRollPitchYaw(truth->rig.kinects[k].T_base_kinect);
      t = truth->rig.kinects[k].T_base_kinect.translation();
    }
    for (int i = 0; i < cal::kKinectParameterCount; ++i) {
      std::optional<double> value;
      if (truth) {
        value = i < 3 ? (*rpy)[i] : i < 6 ? (*t)[i - 3] : truth->rig.kinects[k].latency_s;
      }
      parameters.push_back(ParameterJson(e.parameters[i], value));
    }
    kinects.push_back({{"id", e.id},
                       {"floor", {{"frames", e.floor.frames},
                                  {"roll_deg", e.floor.roll_rad / kDeg},
                                  {"pitch_deg", e.floor.pitch_rad / kDeg},
                                  {"height_m", e.floor.height_m},
                                  {"inlier_share", e.floor.inlier_share},
                                  {"plane_rms_m", e.floor.rms_m}}},
                       {"motion", {{"pairs", e.coverage.pairs},
                                   {"turned_deg", e.coverage.turned_deg},
                                   {"translated_m", e.coverage.translated_m}}}});
    if (truth) {
      kinects.back()["motion"]["error_vs_truth"] =
          SensorMotionErrors(session.capture().kinects[k], static_cast<int>(k), *truth);
    }
  }
  parameters.push_back(ParameterJson(result.scale_left, truth ? std::optional(truth->scale_left) : std::nullopt));
  parameters.push_back(ParameterJson(result.scale_right, truth ? std::optional(truth->scale_right) : std::nullopt));

  auto plots = cal::WriteResidualPlots(result, session.capture(), out_dir.string());
  if (!plots) FailCommand(kCommand, plots.error().message);
  const bool write_rig = result.AllCalibrated() || options.allow_uncalibrated;
  nlohmann::json report = {
      {"mode", truth ? "simulated" : "recording"},
      {"source", truth ? options.world : options.log},
      {"rig_guess", options.rig_guess},
      {"rig_out", options.out},
      {"rig_written", write_rig},
      {"all_calibrated", result.AllCalibrated()},
      {"solver", {{"converged", result.converged},
                  {"summary", result.message},
                  {"residual_sigma_scale", result.residual_sigma_scale},
                  {"outlier_pairs", result.outlier_pairs},
                  {"gyro_bias_rad_s", session.gyro_bias_rad_s()}}},
      {"cross_check", {{"pairs", result.cross_check_pairs},
                       {"rotation_rms_deg", result.cross_check_rotation_rms_deg},
                       {"translation_rms_m", result.cross_check_translation_rms_m}}},
      {"parameters", parameters},
      {"kinects", kinects},
      {"warnings", result.warnings},
      {"plots", *plots}};
  if (truth) {
    // The simulated truth, for comparing maps built with it, the estimate and the guess
    // (dynamap map --rig).
    const std::string truth_file = (out_dir / "rig_truth.yaml").string();
    const robotio::Status saved = robotio::SaveRig(truth->rig, truth_file);
    if (!saved) FailCommand(kCommand, saved.error().message);
    report["seed"] = options.seed;
    report["steps_redone"] = redone;
    report["rig_truth"] = truth_file;
  }
  WriteJsonReport(kCommand, report, (out_dir / "report.json").string());
  if (!write_rig) {
    std::string why;
    for (const std::string& w : result.warnings) why += "\n  " + w;
    FailCommand(kCommand, "rig not written: not every parameter is calibrated (see " +
                              (out_dir / "report.json").string() + "):" + why);
  }
  const robotio::Status saved = session.Save(options.out, options.allow_uncalibrated);
  if (!saved) FailCommand(kCommand, saved.error().message);
  std::printf("%s\n", report.dump(2).c_str());
}

}  // namespace

void RegisterCalibrateCommand(CLI::App& app) {
  auto options = std::make_shared<CalibrateOptions>();
  CLI::App* command = app.add_subcommand(
      kCommand,
      "Calibrate the Kinect rig (floor plane + motion capture + joint refinement) from a "
      "recording or by driving the guided sequence in the simulator");
  command->add_option("--log", options->log, "Recording folder to calibrate from")
      ->check(CLI::ExistingDirectory);
  command->add_option("--world", options->world,
                      "Simulate: world file; the true rig is the guess perturbed per --seed")
      ->check(CLI::ExistingFile);
  command->add_option("--rig-guess", options->rig_guess, "Rig file with the measured guess")
      ->required()
      ->check(CLI::ExistingFile);
  command->add_option("--out", options->out,
                      "Rig file to write; report.json and residual plots go beside it")
      ->required();
  command->add_option("--seed", options->seed, "Simulation seed (truth perturbation, noise)")
      ->capture_default_str();
  command->add_option("--robot", options->robot, "Robot file for --world (default: Segway RMP50)");
  command->add_option("--width", options->width, "Simulated depth width, px")
      ->check(CLI::Range(80, 640))
      ->capture_default_str();
  command->add_option("--max-redos", options->max_redos,
                      "Simulated: capture steps redone while the review names one that would "
                      "calibrate a weak parameter")
      ->check(CLI::Range(0, 10))
      ->capture_default_str();
  command->add_flag("--allow-uncalibrated", options->allow_uncalibrated,
                    "Write the rig even when some parameters are not calibrated (they keep "
                    "their guessed or weak values)");
  command->callback([options] { Run(*options); });
}

}  // namespace dynamap::app
