#include "dynamap/app/gui/MissionWorkspace.hpp"

#include <QHBoxLayout>
#include <QScrollArea>
#include <QScrollBar>
#include <QSplitter>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>

#include "dynamap/app/gui/DepthPreview.hpp"
#include "dynamap/app/gui/GridView.hpp"
#include "dynamap/app/gui/MissionOverlay.hpp"
#include "dynamap/app/gui/MissionPanel.hpp"
#include "dynamap/app/gui/VoxelView.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"

namespace dynamap::app::gui {

MissionWorkspace::MissionWorkspace(QWidget* parent) : QWidget(parent) {
  session_ = new MissionSession(this);
  panel_ = new MissionPanel;
  view_ = new VoxelView;
  grid_ = new GridView;
  depth0_ = new DepthPreview(tr("Kinect 0"));
  depth1_ = new DepthPreview(tr("Kinect 1"));
  overlay_ = std::make_unique<MissionOverlay>(view_->Renderer(), 0.36);

  auto* scroll = new QScrollArea;
  scroll->setWidget(panel_);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  // Never narrower than the panel needs: with no horizontal scroll bar it would be cut.
  const int panel_width = std::max(390, panel_->minimumSizeHint().width() +
                                            scroll->verticalScrollBar()->sizeHint().width());
  scroll->setMinimumWidth(panel_width);

  auto* bottom = new QSplitter(Qt::Horizontal);
  bottom->addWidget(grid_);
  bottom->addWidget(depth0_);
  bottom->addWidget(depth1_);
  bottom->setStretchFactor(0, 3);
  bottom->setStretchFactor(1, 2);
  bottom->setStretchFactor(2, 2);
  auto* views = new QSplitter(Qt::Vertical);
  views->addWidget(view_);
  views->addWidget(bottom);
  views->setStretchFactor(0, 3);
  views->setStretchFactor(1, 2);
  auto* splitter = new QSplitter(Qt::Horizontal);
  splitter->setObjectName(QStringLiteral("mission_splitter"));
  splitter->addWidget(scroll);
  splitter->addWidget(views);
  splitter->setStretchFactor(1, 1);
  splitter->setSizes({panel_width + 10, 1000});
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(splitter);

  connect(panel_, &MissionPanel::StartRequested, this, &MissionWorkspace::StartMission);
  connect(panel_, &MissionPanel::PauseRequested, this, &MissionWorkspace::PauseMission);
  connect(panel_, &MissionPanel::ResumeRequested, this, &MissionWorkspace::ResumeMission);
  connect(panel_, &MissionPanel::StopRequested, this, &MissionWorkspace::StopMission);
  connect(session_, &MissionSession::PhaseChanged, this, &MissionWorkspace::OnPhaseChanged);
  connect(session_, &MissionSession::SnapshotUpdated, this, &MissionWorkspace::OnSnapshot);
  connect(session_, &MissionSession::MapUpdated, this, &MissionWorkspace::OnMapUpdated);
  connect(session_, &MissionSession::ErrorOccurred, this, &MissionWorkspace::ErrorOccurred);
  connect(session_, &MissionSession::Finished, this, [this] {
    panel_->ShowReport(session_->Report(), QString::fromStdString(session_->Config().out_dir));
  });
}

MissionWorkspace::~MissionWorkspace() = default;

bool MissionWorkspace::StartMission() {
  runtime::MissionConfig config = panel_->BuildConfig();
  // Cheap YAML reads for what the views draw; errors surface from the runtime itself.
  if (auto robot = robotio::sim::LoadRobotConfig(config.robot_file)) {
    overlay_ = std::make_unique<MissionOverlay>(view_->Renderer(), robot->footprint_radius_m);
  }
  upside_down_.clear();
  // A replay with its recorded rig reads the recording's rig file.
  const std::string rig_file = config.rig_file.empty() && !config.recording_dir.empty()
                                   ? config.recording_dir + "/rig.yaml"
                                   : config.rig_file;
  if (auto rig = robotio::LoadRig(rig_file)) {
    for (const auto& mount : rig->kinects) {
      upside_down_.push_back(std::abs(robotio::MountRollPitchYaw(mount.T_base_kinect).x()) >
                             M_PI / 2);
    }
  }
  camera_placed_ = false;
  return session_->Start(std::move(config), panel_->BuildRobotSetup());
}

bool MissionWorkspace::Explore(const ExploreRequest& request) {
  panel_->SetWorldFile(request.world_file);
  if (!request.out_dir.isEmpty()) panel_->SetOutputDir(request.out_dir);
  if (request.max_time_s) panel_->SetTimeLimit(*request.max_time_s);
  if (request.poses) panel_->SetPoseSource(*request.poses);
  if (request.kinect_width) {
    panel_->SetKinectSize(*request.kinect_width, *request.kinect_width * 3 / 4);
  }
  return StartMission();  // What the Start button does.
}

bool MissionWorkspace::PauseMission() { return session_->Pause(); }
bool MissionWorkspace::ResumeMission() { return session_->Resume(); }
bool MissionWorkspace::StopMission() { return session_->Stop(); }

void MissionWorkspace::OnPhaseChanged(MissionPhase phase) {
  panel_->ShowPhase(phase);
  const bool has_counts = phase != MissionPhase::kIdle && phase != MissionPhase::kStarting &&
                          phase != MissionPhase::kFailed;
  emit StatusChanged(PhaseName(phase),
                     has_counts ? std::optional<std::uint64_t>(
                                      static_cast<std::uint64_t>(session_->Snapshot().frames_dropped))
                                : std::nullopt);
}

void MissionWorkspace::OnSnapshot() {
  const runtime::MissionSnapshot& s = session_->Snapshot();
  panel_->ShowSnapshot(s);
  panel_->ShowDeadman(session_->DeadmanHeld());
  GridScene scene;
  scene.grid = s.grid;
  scene.pose = s.pose;
  scene.trail = s.trail;
  scene.path = s.path;
  scene.candidates = s.candidates;
  scene.unreachable_frontiers = s.unreachable_frontiers;
  scene.blacklisted_frontiers = s.blacklisted_frontiers;
  scene.has_goal = s.has_goal;
  scene.goal = s.goal;
  grid_->SetScene(std::move(scene));
  for (const robotio::DepthFrame& frame : s.depth) {
    DepthImageOptions options;
    const auto sensor = static_cast<std::size_t>(frame.sensor_id);
    options.rotate_180 = sensor < upside_down_.size() && upside_down_[sensor];
    if (frame.sensor_id == 0) depth0_->SetFrame(frame, options);
    if (frame.sensor_id == 1) depth1_->SetFrame(frame, options);
  }
  if (s.depth.empty()) {
    depth0_->Clear();
    depth1_->Clear();
  }
  // The robot is drawn once the mission has a map to place the camera on.
  if (s.grid) overlay_->SetRobot(s.pose);
  overlay_->SetTrail(s.trail);
  overlay_->SetPath(s.path);
  overlay_->SetGoal(s.has_goal, s.goal);
  if (!camera_placed_ && s.grid) {
    view_->ResetCamera();  // Frames the robot and its surroundings until a map arrives.
  } else {
    view_->Render();
  }
  const MissionPhase phase = session_->Phase();
  if (phase == MissionPhase::kRunning || phase == MissionPhase::kPaused ||
      phase == MissionPhase::kFinished) {
    emit StatusChanged(PhaseName(phase), static_cast<std::uint64_t>(s.frames_dropped));
  }
}

void MissionWorkspace::OnMapUpdated() {
  const bool first = !camera_placed_ && session_->Map() && !session_->Map()->voxels.empty();
  view_->SetVoxels(session_->Map(), VoxelFilter{}, ColourMode::kHeight, first);
  if (first) camera_placed_ = true;
}

}  // namespace dynamap::app::gui
