#include "dynamap/app/gui/MissionSession.hpp"

#include <QFileInfo>

#include "dynamap/app/runtime/MissionRuntime.hpp"
#include "dynamap/app/runtime/RobotSources.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/mapping/MapFiles.hpp"

namespace dynamap::app::gui {

QString PhaseName(MissionPhase phase) {
  switch (phase) {
    case MissionPhase::kIdle:
      return QObject::tr("idle");
    case MissionPhase::kStarting:
      return QObject::tr("starting");
    case MissionPhase::kRunning:
      return QObject::tr("running");
    case MissionPhase::kPaused:
      return QObject::tr("paused");
    case MissionPhase::kFinishing:
      return QObject::tr("finishing");
    case MissionPhase::kFinished:
      return QObject::tr("finished");
    case MissionPhase::kFailed:
      return QObject::tr("failed");
  }
  return QString();
}

MissionSession::MissionSession(QObject* parent) : QObject(parent) {
  lifecycle_task_ = new BackgroundTask(this);
  map_task_ = new BackgroundTask(this);
  poll_timer_.setInterval(250);
  connect(&poll_timer_, &QTimer::timeout, this, &MissionSession::Poll);
  connect(lifecycle_task_, &BackgroundTask::Finished, this,
          [this](bool cancelled, const QString& error) {
            if (!cancelled && !error.isEmpty()) Fail(error);
          });
}

MissionSession::~MissionSession() {
  poll_timer_.stop();
  if (runtime_) runtime_->Stop();
  // The tasks' destructors (children) wait for Create/Finish; the runtime's joins its
  // threads, which leave within one cycle once stopped.
}

namespace {

// Opens the robot's devices for `config` (rig, depth mode) and creates the mission on them;
// the returned runtime keeps the devices open until it is destroyed.
robotio::Expected<std::shared_ptr<runtime::MissionRuntime>> CreateOnRobot(
    const runtime::MissionConfig& config, const RobotSetup& setup,
    const std::shared_ptr<runtime::PadState>& pad_state) {
  namespace hw = robotio::hardware;
  auto rig = robotio::LoadRig(config.rig_file);
  if (!rig) return rig.error();
  for (auto& mount : rig->kinects) {
    mount.intrinsics = mount.intrinsics.Scaled(config.kinect_width, config.kinect_height);
  }
  hw::DriveDevicesConfig drive;
  drive.rmp.device = setup.rmp_port;
  if (!setup.imu_port.empty()) {
    drive.imu.emplace();
    drive.imu->device = setup.imu_port;
  }
  drive.pad.device = setup.pad;
  auto opened = hw::OpenDriveDevices(drive);
  if (!opened) return opened.error();
  auto devices = std::make_shared<hw::RecordingDevices>(std::move(opened).value());
  if (auto cameras = hw::OpenRigCameras(*rig, setup.cameras, devices.get()); !cameras) {
    return cameras.error();
  }
  auto created = runtime::MissionRuntime::CreateOnDevices(
      config, runtime::SourcesFromRobot(*devices, pad_state));
  if (!created) return created.error();
  // The devices are released after the runtime that reads them.
  return std::shared_ptr<runtime::MissionRuntime>(
      created.value().release(), [devices](runtime::MissionRuntime* r) { delete r; });
}

}  // namespace

bool MissionSession::Start(runtime::MissionConfig config, std::optional<RobotSetup> robot) {
  if (phase_ != MissionPhase::kIdle && phase_ != MissionPhase::kFinished &&
      phase_ != MissionPhase::kFailed) {
    return false;
  }
  config_ = std::move(config);
  runtime_.reset();
  report_.reset();
  map_.reset();
  map_loaded_time_ = QDateTime();
  map_copy_version_ = 0;
  map_copy_requested_.invalidate();
  snapshot_ = runtime::MissionSnapshot();
  last_error_.clear();
  pad_state_ = robot ? std::make_shared<runtime::PadState>() : nullptr;
  SetPhase(MissionPhase::kStarting);
  emit SnapshotUpdated();
  emit MapUpdated();
  lifecycle_task_->Start(tr("Starting mission"), [this, config = config_, robot,
                                                  pad_state = pad_state_](
                                                     const BackgroundTask::Context& context) {
    robotio::Expected<std::shared_ptr<runtime::MissionRuntime>> created =
        robot ? CreateOnRobot(config, *robot, pad_state)
              : [&]() -> robotio::Expected<std::shared_ptr<runtime::MissionRuntime>> {
                  auto made = runtime::MissionRuntime::Create(config);
                  if (!made) return made.error();
                  return std::shared_ptr<runtime::MissionRuntime>(std::move(made).value());
                }();
    if (!created) {
      const QString message = QString::fromStdString(created.error().message);
      context.Deliver([this, message] { Fail(message); });
      return;
    }
    std::shared_ptr<runtime::MissionRuntime> runtime = std::move(created).value();
    context.Deliver([this, runtime] {
      runtime_ = runtime;
      runtime_->Start();
      SetPhase(MissionPhase::kRunning);
      poll_timer_.start();
    });
  });
  return true;
}

std::optional<bool> MissionSession::DeadmanHeld() const {
  if (!pad_state_) return std::nullopt;
  return pad_state_->held.load();
}

bool MissionSession::Pause() {
  if (phase_ != MissionPhase::kRunning || !runtime_->Pause()) return false;
  SetPhase(MissionPhase::kPaused);
  return true;
}

bool MissionSession::Resume() {
  if (phase_ != MissionPhase::kPaused || !runtime_->Resume()) return false;
  SetPhase(MissionPhase::kRunning);
  return true;
}

bool MissionSession::Stop() {
  if (phase_ == MissionPhase::kStarting) {
    lifecycle_task_->Cancel();  // The runtime being created is dropped unstarted.
    SetPhase(MissionPhase::kIdle);
    return true;
  }
  if (phase_ != MissionPhase::kRunning && phase_ != MissionPhase::kPaused) return false;
  runtime_->Stop();  // Wakes every worker; Poll() sees the mission stopping.
  Poll();
  return true;
}

void MissionSession::SetPhase(MissionPhase phase) {
  if (phase == phase_) return;
  phase_ = phase;
  emit PhaseChanged(phase);
}

void MissionSession::Fail(const QString& message) {
  poll_timer_.stop();
  last_error_ = message;
  SetPhase(MissionPhase::kFailed);
  emit ErrorOccurred(message);
}

void MissionSession::Poll() {
  if (!runtime_ || (phase_ != MissionPhase::kRunning && phase_ != MissionPhase::kPaused)) return;
  if (pad_state_ && pad_state_->finish.exchange(false)) runtime_->Stop();  // Start on the pad.
  snapshot_ = runtime_->Snapshot();
  emit SnapshotUpdated();
  UpdateLiveMap();
  const auto state = snapshot_.state;
  if (state == runtime::MissionState::kStopping || state == runtime::MissionState::kFinished) {
    BeginFinish();
  }
}

void MissionSession::UpdateLiveMap() {
  if (map_task_->Running()) return;
  auto [tree, version] = runtime_->LatestMapCopy();
  if (tree && version != map_copy_version_) {
    map_copy_version_ = version;
    map_task_->Start(tr("Drawing the mission map"),
                     [this, tree = std::move(tree)](const BackgroundTask::Context& c) {
                       auto voxels = ExtractVoxels(*tree, c.CancelFlag(), [](double) {});
                       if (!voxels) return;
                       auto set = std::make_shared<const VoxelSet>(std::move(*voxels));
                       c.Deliver([this, set] {
                         map_ = set;
                         emit MapUpdated();
                       });
                     });
    return;
  }
  if (!map_copy_requested_.isValid() || map_copy_requested_.elapsed() >= 1000) {
    runtime_->RequestMapCopy();
    map_copy_requested_.restart();
  }
}

void MissionSession::ReloadMapIfNewer() {
  if (map_task_->Running()) return;
  const QString file = QString::fromStdString(config_.out_dir + "/map.ot");
  const QFileInfo info(file);
  if (!info.isFile() || info.lastModified() == map_loaded_time_) return;
  map_loaded_time_ = info.lastModified();
  map_task_->Start(tr("Reading the mission map"), [this, file](const BackgroundTask::Context& c) {
    auto tree = mapping::LoadMap(file.toStdString());
    if (!tree) return;  // The file is replaced atomically; a broken one is not drawn.
    auto voxels = ExtractVoxels(**tree, c.CancelFlag(), [](double) {});
    if (!voxels) return;
    auto set = std::make_shared<const VoxelSet>(std::move(*voxels));
    c.Deliver([this, set] {
      map_ = set;
      emit MapUpdated();
    });
  });
}

void MissionSession::BeginFinish() {
  poll_timer_.stop();
  SetPhase(MissionPhase::kFinishing);
  lifecycle_task_->Start(tr("Scoring the mission"), [this, runtime = runtime_](
                                                        const BackgroundTask::Context& context) {
    auto report = runtime->Finish();  // Joins the runtime's threads, scores, writes files.
    const runtime::MissionSnapshot last = runtime->Snapshot();
    const std::optional<std::string> device_error = runtime->device_error();
    if (!report) {
      const QString message = QString::fromStdString(report.error().message);
      context.Deliver([this, message] { Fail(message); });
      return;
    }
    context.Deliver([this, last, r = *report, device_error] {
      snapshot_ = last;
      report_ = r;
      if (device_error) {
        last_error_ = QString::fromStdString(*device_error);
        emit ErrorOccurred(tr("%1; the base was stopped and the maps so far are saved")
                               .arg(last_error_));
      }
      SetPhase(MissionPhase::kFinished);
      emit SnapshotUpdated();
      map_loaded_time_ = QDateTime();  // Finish() wrote the final map.
      ReloadMapIfNewer();
      emit Finished();
    });
  });
}

}  // namespace dynamap::app::gui
