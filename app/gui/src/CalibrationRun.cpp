#include "dynamap/app/gui/CalibrationRun.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <random>

#include "dynamap/calibration/CaptureReplay.hpp"
#include "dynamap/calibration/ResidualPlot.hpp"
#include "dynamap/robotio/RecordingReader.hpp"
#include "dynamap/robotio/Time.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"
#include "dynamap/robotio/sim/Simulator.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app::gui {

namespace cal = calibration;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kStepS = 0.05;          // s of simulated time per loop iteration.
constexpr double kPublishPeriodS = 0.1;  // s of wall time between published states.

// One scripted motion of "drive this step for me": held until `done` or `max_s`.
struct Phase {
  double v = 0.0;
  double omega = 0.0;
  std::function<bool(const cal::SessionProgress&)> done;
  double max_s = 40.0;
};

// The guided motions of a capture step, as an operator would drive them.
std::deque<Phase> ScriptFor(cal::SessionStep step, const cal::SessionConfig& c) {
  const auto pause = [] { return Phase{0.0, 0.0, [](const cal::SessionProgress&) { return false; }, 1.0}; };
  switch (step) {
    case cal::SessionStep::kFloor:
      return {{0.0, 0.0, [](const cal::SessionProgress& p) { return p.complete; }, 15.0}};
    case cal::SessionStep::kTurn:
      return {{0.0, 0.5, [c](const cal::SessionProgress& p) { return p.turned_left_deg >= c.turn_target_deg; }},
              pause(),
              {0.0, -0.5, [c](const cal::SessionProgress& p) { return p.turned_right_deg >= c.turn_target_deg; }},
              pause()};
    case cal::SessionStep::kStraight:
      return {{0.3, 0.0, [c](const cal::SessionProgress& p) { return p.forward_m >= c.straight_target_m; }},
              pause(),
              {-0.3, 0.0, [c](const cal::SessionProgress& p) { return p.backward_m >= c.straight_target_m; }},
              pause()};
    case cal::SessionStep::kArcs:
      return {{0.3, 0.4, [c](const cal::SessionProgress& p) { return p.arc_left_m >= c.arc_target_m; }},
              pause(),
              {-0.3, -0.4, [c](const cal::SessionProgress& p) { return p.arc_right_m >= c.arc_target_m; }},
              pause()};
    default:
      return {};
  }
}

bool IsCaptureStep(cal::SessionStep step) {
  return step == cal::SessionStep::kFloor || step == cal::SessionStep::kTurn ||
         step == cal::SessionStep::kStraight || step == cal::SessionStep::kArcs;
}

}  // namespace

robotio::Rig SimulatedRigTruth(const robotio::Rig& guess, const CalibrationSetup& setup) {
  std::mt19937_64 rng(setup.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  robotio::Rig truth = guess;
  for (robotio::KinectMount& m : truth.kinects) {
    Eigen::Vector3d rpy = robotio::MountRollPitchYaw(m.T_base_kinect);
    Eigen::Vector3d t = m.T_base_kinect.translation();
    for (int i = 0; i < 3; ++i) rpy[i] += setup.max_angle_deg * kDeg * unit(rng);
    for (int i = 0; i < 3; ++i) t[i] += setup.max_offset_m * unit(rng);
    m.T_base_kinect = robotio::MountPose(t, rpy);
    m.latency_s = setup.true_latency_s;
    m.rate_hz = 10.0;  // Keyframes are 0.5 s apart; 30 Hz would only cost rendering time.
    const int height = setup.width * m.intrinsics.height / m.intrinsics.width;
    m.intrinsics = m.intrinsics.Scaled(setup.width, height);
  }
  return truth;
}

struct CalibrationRun::Impl {
  Impl(cal::CalibrationSession s, cal::SessionConfig c)
      : session(std::move(s)), config(std::move(c)) {}
  std::optional<robotio::sim::Simulator> simulator;       // Simulated session ...
  std::unique_ptr<robotio::RecordingReader> reader;       // ... or a recording replayed.
  std::unique_ptr<cal::CaptureReplay> replay;
  std::int64_t replay_ns = 0;  // Recorded time fed up to.
  bool replay_failed = false;
  cal::CalibrationSession session;
  cal::SessionConfig config;
  double v = 0.0;
  double omega = 0.0;
  std::deque<Phase> script;
  double phase_elapsed_s = 0.0;
  std::vector<robotio::DepthFrame> depth;
};

robotio::Expected<std::unique_ptr<CalibrationRun>> CalibrationRun::Create(
    const CalibrationSetup& setup) {
  auto guess = robotio::LoadRig(setup.rig_guess_file);
  if (!guess) return guess.error();
  auto robot = robotio::sim::LoadRobotConfig(setup.robot_file);
  if (!robot) return robot.error();
  std::unique_ptr<robotio::RecordingReader> reader;
  std::optional<robotio::sim::World> world;
  if (!setup.recording_dir.empty()) {
    auto opened = robotio::RecordingReader::Open(setup.recording_dir);
    if (!opened) return opened.error();
    if (opened->odometry().empty() || opened->depth_entries().empty()) {
      return robotio::Error{setup.recording_dir +
                            ": a calibration recording needs odometry.txt and depth frames"};
    }
    reader = std::make_unique<robotio::RecordingReader>(std::move(*opened));
  } else {
    auto loaded = robotio::sim::LoadWorld(setup.world_file);
    if (!loaded) return loaded.error();
    world = std::move(*loaded);
  }
  std::error_code ec;
  std::filesystem::create_directories(setup.out_dir, ec);
  if (ec) return robotio::Error{setup.out_dir + ": cannot create the output folder"};

  cal::SessionConfig config;
  config.track_width_m = robot->track_width_m;
  // A recording's true rig is unknown (empty); the simulator's is the guess perturbed.
  const robotio::Rig truth = reader ? robotio::Rig{} : SimulatedRigTruth(*guess, setup);
  std::unique_ptr<CalibrationRun> run(new CalibrationRun(setup, *guess, truth));
  run->robot_radius_m_ = robot->footprint_radius_m;
  run->impl_ = std::make_unique<Impl>(cal::CalibrationSession(*guess, config), config);
  if (reader) {
    run->impl_->replay = std::make_unique<cal::CaptureReplay>(*reader);
    run->impl_->replay_ns = reader->first_stamp_ns();
    run->impl_->reader = std::move(reader);
    run->state_.replay = true;
  } else {
    run->true_scale_left_ = 1.0 / (1.0 + robot->encoder_scale_error_left);
    run->true_scale_right_ = 1.0 / (1.0 + robot->encoder_scale_error_right);
    robotio::sim::SimulatorConfig sim_config;
    sim_config.seed = setup.seed;
    run->impl_->simulator.emplace(*world, *robot, truth, sim_config);
  }
  run->impl_->depth.resize(guess->kinects.size());
  run->state_.progress = run->impl_->session.Progress();
  run->thread_ = std::thread([r = run.get()] { r->Loop(); });
  return run;
}

CalibrationRun::CalibrationRun(CalibrationSetup setup, robotio::Rig guess, robotio::Rig truth)
    : setup_(std::move(setup)), guess_(std::move(guess)), truth_(std::move(truth)) {}

CalibrationRun::~CalibrationRun() {
  quit_ = true;
  queue_changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void CalibrationRun::Post(std::function<void()> request) {
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    queue_.push_back(std::move(request));
  }
  queue_changed_.notify_all();
}

namespace {
void Report(std::mutex& mutex, CalibrationState& state, const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex);
  state.message = message;
  ++state.message_serial;
}
constexpr const char* kRecordedNotDriven = "a recording cannot be driven: it replays as recorded";
}  // namespace

void CalibrationRun::Drive(double v_mps, double omega_radps) {
  Post([this, v_mps, omega_radps] {
    if (!impl_->simulator) return Report(state_mutex_, state_, kRecordedNotDriven);
    impl_->script.clear();
    impl_->v = v_mps;
    impl_->omega = omega_radps;
  });
}

void CalibrationRun::DriveCurrentStep() {
  Post([this] {
    if (!impl_->simulator) return Report(state_mutex_, state_, kRecordedNotDriven);
    impl_->script = ScriptFor(impl_->session.step(), impl_->config);
    impl_->phase_elapsed_s = 0.0;
  });
}

void CalibrationRun::Advance() {
  Post([this] {
    impl_->script.clear();
    impl_->v = impl_->omega = 0.0;
    if (auto status = impl_->session.Advance(); !status) {
      Report(state_mutex_, state_, status.error().message);
    }
  });
}

void CalibrationRun::Skip() {
  Post([this] {
    impl_->script.clear();
    impl_->v = impl_->omega = 0.0;
    impl_->session.Skip();
  });
}

void CalibrationRun::Solve() {
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    state_.solving = true;
  }
  Post([this] {
    impl_->script.clear();
    impl_->v = impl_->omega = 0.0;
    const cal::SolverResult& result = impl_->session.Solve();
    auto shared = std::make_shared<const cal::SolverResult>(result);
    auto plots = cal::WriteResidualPlots(result, impl_->session.capture(), setup_.out_dir);
    std::lock_guard<std::mutex> lock(state_mutex_);
    state_.solving = false;
    state_.result = shared;
    state_.plots = plots ? *plots : std::vector<std::string>{};
    if (!plots) {
      state_.message = plots.error().message;
      ++state_.message_serial;
    }
  });
}

void CalibrationRun::Redo(cal::SessionStep step) {
  Post([this, step] { impl_->session.Redo(step); });
}

void CalibrationRun::Save(const std::string& file, bool allow_uncalibrated) {
  Post([this, file, allow_uncalibrated] {
    const auto status = impl_->session.Save(file, allow_uncalibrated);
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (status) {
      state_.saved_file = file;
    } else {
      state_.message = status.error().message;
      ++state_.message_serial;
    }
  });
}

CalibrationState CalibrationRun::State() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return state_;
}

void CalibrationRun::CaptureStep() {
  Impl& m = *impl_;
  if (!m.simulator) {
    m.replay_ns += robotio::SecondsToNanos(kStepS);
    if (auto fed = m.replay->FeedUntil(m.session, m.replay_ns, &m.depth); !fed) {
      m.replay_failed = true;
      Report(state_mutex_, state_, fed.error().message);
    }
    return;
  }
  if (!m.script.empty()) {
    const Phase& phase = m.script.front();
    m.v = phase.v;
    m.omega = phase.omega;
  }
  m.simulator->SetCommand({m.simulator->now_ns(), m.v, m.omega});
  const robotio::sim::SimOutput out = m.simulator->Advance(kStepS);
  std::size_t i = 0, j = 0;
  while (i < out.odometry.size() || j < out.imu.size()) {
    if (j >= out.imu.size() ||
        (i < out.odometry.size() && out.odometry[i].stamp_ns <= out.imu[j].stamp_ns)) {
      m.session.AddOdometry(out.odometry[i++]);
    } else {
      m.session.AddImu(out.imu[j++]);
    }
  }
  for (const auto& frame : out.frames) {
    m.session.AddDepth(frame.depth);
    const auto sensor = static_cast<std::size_t>(frame.depth.sensor_id);
    if (sensor < m.depth.size()) m.depth[sensor] = frame.depth;
  }
  if (!m.script.empty()) {
    m.phase_elapsed_s += kStepS;
    const Phase& phase = m.script.front();
    if (phase.done(m.session.Progress()) || m.phase_elapsed_s >= phase.max_s) {
      m.script.pop_front();
      m.phase_elapsed_s = 0.0;
      if (m.script.empty()) m.v = m.omega = 0.0;
    }
  }
}

void CalibrationRun::Loop() {
  using Clock = std::chrono::steady_clock;
  const auto wall_start = Clock::now();
  auto last_publish = Clock::time_point();
  double sim_s = 0.0;
  while (!quit_) {
    std::deque<std::function<void()>> requests;
    {
      std::lock_guard<std::mutex> lock(queue_mutex_);
      requests.swap(queue_);
    }
    for (auto& request : requests) request();

    Impl& m = *impl_;
    // A replay that has fed its whole recording waits, like the steps after capture.
    const bool replay_over = !m.simulator && (m.replay->done() || m.replay_failed);
    const bool capturing = IsCaptureStep(m.session.step()) && !replay_over;
    if (capturing) {
      CaptureStep();
      sim_s += kStepS;
    } else {
      m.v = m.omega = 0.0;
      m.script.clear();
    }

    const auto now = Clock::now();
    if (!requests.empty() || !capturing ||
        std::chrono::duration<double>(now - last_publish).count() >= kPublishPeriodS) {
      last_publish = now;
      CalibrationState published;
      {
        std::lock_guard<std::mutex> lock(state_mutex_);
        published = state_;
      }
      published.progress = m.session.Progress();
      published.sim_time_s =
          m.simulator ? robotio::NanosToSeconds(m.simulator->now_ns())
                      : robotio::NanosToSeconds(m.replay_ns - m.reader->first_stamp_ns());
      published.auto_driving = !m.script.empty();
      published.driving = m.v != 0.0 || m.omega != 0.0;
      published.depth = m.depth;
      published.floor.clear();
      for (const auto& kinect : m.session.capture().kinects) {
        published.floor.push_back(kinect.floor.empty()
                                      ? std::nullopt
                                      : std::optional<cal::PlaneFit>(kinect.floor.back()));
      }
      published.collisions = m.simulator ? m.simulator->collision_count() : 0;
      published.replay_fraction = m.replay ? m.replay->fraction() : 0.0;
      std::lock_guard<std::mutex> lock(state_mutex_);
      // Fields the requests own (result, plots, saved file, messages) stay as they are.
      state_.progress = published.progress;
      state_.sim_time_s = published.sim_time_s;
      state_.auto_driving = published.auto_driving;
      state_.driving = published.driving;
      state_.depth = std::move(published.depth);
      state_.floor = std::move(published.floor);
      state_.collisions = published.collisions;
      state_.replay_fraction = published.replay_fraction;
    }

    if (!capturing) {
      // Nothing to simulate between solve, review and save: wait for the next request.
      std::unique_lock<std::mutex> lock(queue_mutex_);
      queue_changed_.wait_for(lock, std::chrono::milliseconds(100),
                              [this] { return quit_ || !queue_.empty(); });
    } else if (setup_.speed > 0.0) {
      const auto due = wall_start + std::chrono::duration_cast<Clock::duration>(
                                        std::chrono::duration<double>(sim_s / setup_.speed));
      std::unique_lock<std::mutex> lock(queue_mutex_);
      queue_changed_.wait_until(lock, due, [this] { return quit_.load(); });
    }
  }
}

}  // namespace dynamap::app::gui
