#include "dynamap/app/gui/MissionPanel.hpp"

#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>

#include "dynamap/app/gui/ResourceFiles.hpp"
#include "dynamap/robotio/hardware/GamepadTeleop.hpp"
#include "dynamap/robotio/hardware/RmpDriver.hpp"
#include "dynamap/robotio/hardware/XsensImu.hpp"

namespace dynamap::app::gui {

namespace {

QLabel* Value() {
  auto* label = new QLabel(QStringLiteral("–"));
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  label->setWordWrap(true);  // Long values wrap rather than widen the panel.
  return label;
}

// A figure, or "–" when it is not known (NaN: no ground truth on the robot).
QString Figure(double value, int decimals, double scale = 1.0) {
  return std::isfinite(value) ? QString::number(value * scale, 'f', decimals) : QStringLiteral("–");
}

// File lists show short names; a long one must not widen the panel.
void KeepNarrow(QComboBox* combo) {
  combo->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  combo->setMinimumContentsLength(14);
}

void FillFiles(QComboBox* combo, const QStringList& files, const QString& preferred) {
  for (const QString& file : files) combo->addItem(QFileInfo(file).fileName(), file);
  const int index = combo->findText(preferred);
  if (index >= 0) combo->setCurrentIndex(index);
}

void SelectFile(QComboBox* combo, const QString& file) {
  const QString path = QFileInfo(file).absoluteFilePath();
  int index = combo->findData(path);
  if (index < 0) {
    combo->addItem(QFileInfo(file).fileName(), path);
    index = combo->count() - 1;
  }
  combo->setCurrentIndex(index);
}

}  // namespace

MissionPanel::MissionPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  setup_ = MakeSetupGroup();
  layout->addWidget(setup_);

  start_ = new QPushButton(style()->standardIcon(QStyle::SP_MediaPlay), tr("Start"));
  pause_ = new QPushButton(style()->standardIcon(QStyle::SP_MediaPause), tr("Pause"));
  resume_ = new QPushButton(style()->standardIcon(QStyle::SP_MediaPlay), tr("Resume"));
  stop_ = new QPushButton(style()->standardIcon(QStyle::SP_MediaStop), tr("Stop"));
  start_->setObjectName(QStringLiteral("mission_start"));
  start_->setToolTip(tr("Start the mission (F9)"));
  start_->setShortcut(Qt::Key_F9);
  pause_->setToolTip(tr("Pause every runtime thread within one cycle (F10)"));
  pause_->setShortcut(Qt::Key_F10);
  resume_->setToolTip(tr("Carry on (F10)"));
  resume_->setShortcut(Qt::Key_F10);
  stop_->setToolTip(tr("End the mission; the results are still scored and saved (Shift+F9)"));
  stop_->setShortcut(Qt::SHIFT | Qt::Key_F9);
  auto* buttons = new QHBoxLayout;
  for (QPushButton* b : {start_, pause_, resume_, stop_}) buttons->addWidget(b);
  layout->addLayout(buttons);
  connect(start_, &QPushButton::clicked, this, &MissionPanel::StartRequested);
  connect(pause_, &QPushButton::clicked, this, &MissionPanel::PauseRequested);
  connect(resume_, &QPushButton::clicked, this, &MissionPanel::ResumeRequested);
  connect(stop_, &QPushButton::clicked, this, &MissionPanel::StopRequested);

  layout->addWidget(MakeFiguresGroup());
  ShowDeadman(std::nullopt);
  auto* report_box = new QGroupBox(tr("Report"));
  auto* report_layout = new QVBoxLayout(report_box);
  report_ = new QLabel(tr("Shown when the mission has ended."));
  report_->setWordWrap(true);
  report_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  report_layout->addWidget(report_);
  layout->addWidget(report_box);
  layout->addStretch(1);
  ShowPhase(MissionPhase::kIdle);
}

QWidget* MissionPanel::MakeSetupGroup() {
  auto* box = new QGroupBox(tr("Mission"));
  auto* form = new QFormLayout(box);
  setup_form_ = form;
  const auto with_browse = [this](QWidget* field, const QString& title,
                                  const std::function<void()>& browse_action) {
    auto* row = new QWidget;
    auto* layout = new QHBoxLayout(row);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(field, 1);
    auto* browse = new QToolButton;
    browse->setText(QStringLiteral("…"));
    browse->setToolTip(title);
    connect(browse, &QToolButton::clicked, this, browse_action);
    layout->addWidget(browse);
    return row;
  };
  source_ = new QComboBox;
  source_->setObjectName(QStringLiteral("mission_source"));
  source_->addItem(tr("Simulated world"));
  source_->addItem(tr("Recording"));
  source_->addItem(tr("Real robot"));
  source_->setToolTip(tr("Explore a simulated world; replay a recording through the mission "
                         "(mapping and planning run, the robot is not steered); or explore "
                         "with the real robot, which moves only while the pad's LB is held"));
  form->addRow(tr("Source"), source_);
  world_ = new QComboBox;
  FillFiles(world_, ResourceFiles(QStringLiteral("worlds")), QStringLiteral("office.yaml"));
  KeepNarrow(world_);
  world_row_ = with_browse(world_, tr("Choose a world file"),
                           [this] { BrowseFile(world_, tr("Choose a world file")); });
  form->addRow(tr("World"), world_row_);
  recording_ = new QLineEdit;
  recording_->setObjectName(QStringLiteral("mission_recording"));
  recording_->setPlaceholderText(tr("recording folder (dynamap record, explore --record)"));
  recording_row_ = with_browse(recording_, tr("Choose a recording folder"), [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Choose a recording folder"),
                                                          recording_->text());
    if (!dir.isEmpty()) recording_->setText(dir);
  });
  form->addRow(tr("Recording"), recording_row_);
  robot_box_ = new QWidget;
  auto* robot_form = new QFormLayout(robot_box_);
  robot_form->setContentsMargins(0, 0, 0, 0);
  rmp_port_ = new QLineEdit(QString::fromStdString(robotio::hardware::RmpConfig{}.device));
  rmp_port_->setObjectName(QStringLiteral("mission_rmp_port"));
  imu_port_ = new QLineEdit(QString::fromStdString(robotio::hardware::XsensImuConfig{}.device));
  imu_port_->setPlaceholderText(tr("none: heading from the wheels"));
  pad_ = new QLineEdit(QString::fromStdString(robotio::hardware::GamepadConfig{}.device));
  cameras_ = new QLineEdit;
  cameras_->setPlaceholderText(tr("serial:XYZ, serial:ABC (one per rig Kinect)"));
  cameras_->setToolTip(tr("One per Kinect of the rig, in rig order: an OpenNI2 URI, serial:XYZ "
                          "or N for the N-th camera OpenNI2 lists; empty for a one-Kinect rig"));
  robot_form->addRow(tr("RMP port"), rmp_port_);
  robot_form->addRow(tr("Gyro port"), imu_port_);
  robot_form->addRow(tr("Gamepad"), pad_);
  robot_form->addRow(tr("Kinects"), cameras_);
  form->addRow(robot_box_);
  rig_ = new QComboBox;
  rig_->addItem(tr("As recorded"), QString());
  FillFiles(rig_, ResourceFiles(QStringLiteral("rigs")), QStringLiteral("two_kinects.yaml"));
  KeepNarrow(rig_);
  form->addRow(tr("Rig"), with_browse(rig_, tr("Choose a rig file"),
                                      [this] { BrowseFile(rig_, tr("Choose a rig file")); }));
  connect(source_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this] { ShowSource(); });
  poses_ = new QComboBox;
  poses_->addItem(tr("SLAM"), static_cast<int>(runtime::PoseSource::kSlam));
  poses_->addItem(tr("Odometry"), static_cast<int>(runtime::PoseSource::kOdometry));
  poses_->addItem(tr("Ground truth"), static_cast<int>(runtime::PoseSource::kGroundTruth));
  form->addRow(tr("Poses"), poses_);
  targets_ = new QComboBox;
  targets_->setObjectName(QStringLiteral("mission_targets"));
  targets_->addItem(tr("Tour through all targets"), QStringLiteral("tour"));
  targets_->addItem(tr("Gain over path cost"), QStringLiteral("gain"));
  targets_->addItem(tr("Nearest frontier (baseline)"), QStringLiteral("nearest-frontier"));
  targets_->setToolTip(tr("How the next target is chosen: the first stop of the shortest "
                          "tour through all targets back to the start, the best gain over "
                          "path cost, or Yamauchi's nearest frontier without inspection"));
  SetTargetStrategy(QString::fromStdString(planning::TargetPlannerConfig{}.strategy));
  KeepNarrow(targets_);
  form->addRow(tr("Targets"), targets_);
  kinect_size_ = new QComboBox;
  for (const QSize size : {QSize(160, 120), QSize(320, 240), QSize(640, 480)}) {
    kinect_size_->addItem(QStringLiteral("%1 × %2").arg(size.width()).arg(size.height()), size);
  }
  kinect_size_->setCurrentIndex(1);
  form->addRow(tr("Kinect images"), kinect_size_);
  time_limit_ = new QDoubleSpinBox;
  time_limit_->setRange(1.0, 7200.0);
  time_limit_->setDecimals(0);
  time_limit_->setSuffix(tr(" s"));
  time_limit_->setValue(600.0);
  form->addRow(tr("Time limit"), time_limit_);
  pace_ = new QComboBox;
  pace_->addItem(tr("As fast as possible"), 0.0);
  pace_->addItem(tr("Real time"), 1.0);
  pace_->setToolTip(tr("Real time drops the frames the mapper cannot keep up with, as on the robot"));
  form->addRow(tr("Pace"), pace_);
  save_period_ = new QDoubleSpinBox;
  save_period_->setRange(1.0, 600.0);
  save_period_->setDecimals(0);
  save_period_->setSuffix(tr(" s"));
  save_period_->setValue(30.0);
  save_period_->setToolTip(tr("Simulated seconds between the periodic saves of map.ot (what "
                              "a crash leaves); the 3D view follows the map live"));
  form->addRow(tr("Map saved every"), save_period_);
  out_dir_ = new QLineEdit;
  out_dir_->setPlaceholderText(tr("new folder in ~/dynamap-missions"));
  form->addRow(tr("Results"), out_dir_);
  ShowSource();
  return box;
}

bool MissionPanel::ReplaysRecording() const { return source_->currentIndex() == 1; }
bool MissionPanel::RunsOnRobot() const { return source_->currentIndex() == 2; }

std::optional<RobotSetup> MissionPanel::BuildRobotSetup() const {
  if (!RunsOnRobot()) return std::nullopt;
  RobotSetup setup;
  setup.rmp_port = rmp_port_->text().trimmed().toStdString();
  setup.imu_port = imu_port_->text().trimmed().toStdString();
  setup.pad = pad_->text().trimmed().toStdString();
  for (const QString& camera : cameras_->text().split(QLatin1Char(','), Qt::SkipEmptyParts)) {
    if (!camera.trimmed().isEmpty()) setup.cameras.push_back(camera.trimmed().toStdString());
  }
  return setup;
}

void MissionPanel::SetRobot(const RobotSetup& setup) {
  source_->setCurrentIndex(2);
  rmp_port_->setText(QString::fromStdString(setup.rmp_port));
  imu_port_->setText(QString::fromStdString(setup.imu_port));
  pad_->setText(QString::fromStdString(setup.pad));
  QStringList cameras;
  for (const std::string& c : setup.cameras) cameras << QString::fromStdString(c);
  cameras_->setText(cameras.join(QStringLiteral(", ")));
}

void MissionPanel::ShowSource() {
  const bool replay = ReplaysRecording();
  const auto show_row = [this](QWidget* field, bool visible) {
    field->setVisible(visible);
    if (QWidget* label = setup_form_->labelForField(field)) label->setVisible(visible);
  };
  const bool robot = RunsOnRobot();
  show_row(world_row_, !replay && !robot);
  show_row(recording_row_, replay);
  robot_box_->setVisible(robot);
  // A replay has the recorded images and rig; a simulation needs a rig file; the robot
  // runs in real time.
  kinect_size_->setEnabled(!replay);
  pace_->setEnabled(!robot);
  if (replay) {
    rig_->setCurrentIndex(0);
  } else if (rig_->currentData().toString().isEmpty()) {
    rig_->setCurrentIndex(std::max(0, rig_->findText(QStringLiteral("two_kinects.yaml"))));
  }
  time_limit_->setToolTip(replay  ? tr("Recorded time after which the replay is ended (at "
                                       "most the recording's length)")
                          : robot ? tr("Time after which the mission on the robot is ended")
                                  : tr("Simulated time after which the mission is ended"));
}

QWidget* MissionPanel::MakeFiguresGroup() {
  auto* box = new QGroupBox(tr("Live"));
  auto* form = new QFormLayout(box);
  figures_form_ = form;
  state_ = Value();
  sim_time_ = Value();
  distance_ = Value();
  frames_ = Value();
  dropped_ = Value();
  collisions_ = Value();
  target_ = Value();
  command_ = Value();
  ate_ = Value();
  explored_ = Value();
  progress_ = new QProgressBar;
  progress_->setObjectName(QStringLiteral("mission_progress"));
  progress_->setRange(0, 1000);
  progress_->setValue(0);
  progress_->setFormat(QStringLiteral("–"));
  deadman_ = Value();
  form->addRow(tr("State"), state_);
  form->addRow(tr("Dead-man (LB)"), deadman_);
  form->addRow(tr("Progress"), progress_);
  form->addRow(tr("Mission time"), sim_time_);
  form->addRow(tr("Distance driven"), distance_);
  form->addRow(tr("Frames mapped"), frames_);
  form->addRow(tr("Frames dropped"), dropped_);
  form->addRow(tr("Collisions"), collisions_);
  form->addRow(tr("Explored"), explored_);
  form->addRow(tr("ATE so far"), ate_);
  form->addRow(tr("Target"), target_);
  form->addRow(tr("Command"), command_);
  return box;
}

void MissionPanel::BrowseFile(QComboBox* combo, const QString& title) {
  const QString start = QFileInfo(combo->currentData().toString()).absolutePath();
  const QString file =
      QFileDialog::getOpenFileName(this, title, start, tr("YAML files (*.yaml);;All files (*)"));
  if (!file.isEmpty()) SelectFile(combo, file);
}

runtime::MissionConfig MissionPanel::BuildConfig() const {
  runtime::MissionConfig config;
  if (ReplaysRecording()) {
    config.recording_dir = recording_->text().trimmed().toStdString();
  } else if (!RunsOnRobot()) {
    config.world_file = world_->currentData().toString().toStdString();
  }
  config.rig_file = rig_->currentData().toString().toStdString();
  // The runtime loads exactly the files it is given.
  config.robot_file = ResourcePath(QStringLiteral("robots/segway_rmp50.yaml")).toStdString();
  config.poses = static_cast<runtime::PoseSource>(poses_->currentData().toInt());
  config.planning.targets.strategy = targets_->currentData().toString().toStdString();
  const QSize size = kinect_size_->currentData().toSize();
  config.kinect_width = size.width();
  config.kinect_height = size.height();
  config.max_time_s = time_limit_->value();
  config.speed = pace_->currentData().toDouble();
  config.save_period_s = save_period_->value();
  QString out = out_dir_->text().trimmed();
  if (out.isEmpty()) {
    out = QDir::home().filePath(
        QStringLiteral("dynamap-missions/%1")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss"))));
  }
  config.out_dir = out.toStdString();
  return config;
}

void MissionPanel::SetWorldFile(const QString& file) {
  source_->setCurrentIndex(0);
  SelectFile(world_, file);
}

void MissionPanel::SetRecording(const QString& dir) {
  source_->setCurrentIndex(1);
  recording_->setText(dir);
}
void MissionPanel::SetRigFile(const QString& file) { SelectFile(rig_, file); }

void MissionPanel::SetPoseSource(runtime::PoseSource source) {
  poses_->setCurrentIndex(poses_->findData(static_cast<int>(source)));
}

void MissionPanel::SetTargetStrategy(const QString& strategy) {
  const int index = targets_->findData(strategy);
  if (index >= 0) targets_->setCurrentIndex(index);
}

void MissionPanel::SetKinectSize(int width, int height) {
  const int index = kinect_size_->findData(QSize(width, height));
  if (index >= 0) {
    kinect_size_->setCurrentIndex(index);
  } else {
    kinect_size_->addItem(QStringLiteral("%1 × %2").arg(width).arg(height), QSize(width, height));
    kinect_size_->setCurrentIndex(kinect_size_->count() - 1);
  }
}

void MissionPanel::SetTimeLimit(double seconds) { time_limit_->setValue(seconds); }
void MissionPanel::SetSavePeriod(double seconds) { save_period_->setValue(seconds); }
void MissionPanel::SetOutputDir(const QString& dir) { out_dir_->setText(dir); }

void MissionPanel::ShowPhase(MissionPhase phase) {
  const bool idle = phase == MissionPhase::kIdle || phase == MissionPhase::kFinished ||
                    phase == MissionPhase::kFailed;
  setup_->setEnabled(idle);
  start_->setEnabled(idle);
  pause_->setEnabled(phase == MissionPhase::kRunning);
  resume_->setEnabled(phase == MissionPhase::kPaused);
  stop_->setEnabled(phase == MissionPhase::kStarting || phase == MissionPhase::kRunning ||
                    phase == MissionPhase::kPaused);
  pause_->setVisible(phase != MissionPhase::kPaused);
  resume_->setVisible(phase == MissionPhase::kPaused);
  state_->setText(PhaseName(phase));
  if (phase == MissionPhase::kStarting) report_->setText(tr("Shown when the mission has ended."));
}

void MissionPanel::ShowSnapshot(const runtime::MissionSnapshot& s) {
  sim_time_->setText(tr("%1 s").arg(s.sim_time_s, 0, 'f', 1));
  if (s.time_limit_s > 0.0) {
    const double fraction = std::clamp(s.sim_time_s / s.time_limit_s, 0.0, 1.0);
    progress_->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
    progress_->setFormat(tr("%1 of %2 s").arg(s.sim_time_s, 0, 'f', 0).arg(s.time_limit_s, 0, 'f', 0));
  }
  explored_->setText(s.explored_free_fraction
                         ? tr("%1 % of the reachable floor").arg(100.0 * *s.explored_free_fraction, 0, 'f', 1)
                         : tr("– (no ground truth)"));
  ate_->setText(s.ate_so_far_m ? tr("%1 m").arg(*s.ate_so_far_m, 0, 'f', 3)
                               : tr("– (no ground truth)"));
  distance_->setText(tr("%1 m").arg(s.distance_m, 0, 'f', 2));
  frames_->setText(tr("%1 of %2").arg(s.frames_processed).arg(s.frames_delivered));
  dropped_->setText(QString::number(s.frames_dropped));
  collisions_->setText(tr("%1 (guard stops %2)").arg(s.collisions).arg(s.guard_stops));
  target_->setText(s.has_goal ? tr("%1 at (%2, %3) m, %4 candidates")
                                    .arg(QString::fromLatin1(planning::TargetKindName(s.target_kind)))
                                    .arg(s.goal.x(), 0, 'f', 1)
                                    .arg(s.goal.y(), 0, 'f', 1)
                                    .arg(s.candidates.size())
                              : (s.exploration_done ? tr("exploration done") : tr("none")));
  command_->setText(tr("v %1 m/s, ω %2 rad/s").arg(s.command.v, 0, 'f', 2).arg(s.command.omega, 0, 'f', 2));
}

void MissionPanel::ShowReport(const std::optional<runtime::MissionReport>& report,
                              const QString& out_dir) {
  if (!report) return;
  const runtime::MissionReport& r = *report;
  report_->setText(
      tr("<b>%1</b> after %2 s<br>"
         "explored free area %3 %, surfaces %4 %<br>"
         "path %5 m, collisions %6<br>"
         "ATE %7 m (odometry alone %8 m)<br>"
         "static / dynamic / associated accuracy %9 / %10 / %11<br>"
         "frames %12 mapped, %13 dropped<br>"
         "results in <tt>%14</tt>")
          .arg(r.completed ? tr("Exploration complete") : tr("Mission ended"))
          .arg(r.mission_time_s, 0, 'f', 1)
          .arg(Figure(r.explored_free_fraction, 1, 100.0))
          .arg(Figure(r.surface_coverage, 1, 100.0))
          .arg(r.path_length_m, 0, 'f', 2)
          .arg(r.collisions)
          .arg(Figure(r.ate_rmse_m, 3))
          .arg(Figure(r.odometry_ate_rmse_m, 3))
          .arg(Figure(r.static_accuracy, 3))
          .arg(Figure(r.dynamic_accuracy, 3))
          .arg(Figure(r.associated_accuracy, 3))
          .arg(r.frames_processed)
          .arg(r.frames_dropped)
          .arg(out_dir.toHtmlEscaped()));
}

void MissionPanel::ShowDeadman(std::optional<bool> held) {
  deadman_->setVisible(held.has_value());
  if (QWidget* label = figures_form_->labelForField(deadman_)) label->setVisible(held.has_value());
  if (held) {
    deadman_->setText(*held ? tr("held: the base follows the planner")
                            : tr("released: the base is held still"));
  }
}

QString MissionPanel::FiguresText() const {
  return QStringList{state_->text(),    progress_->text(),   sim_time_->text(),
                     distance_->text(), frames_->text(),     dropped_->text(),
                     collisions_->text(), explored_->text(), ate_->text(),
                     target_->text()}
      .join(QStringLiteral(" | "));
}

}  // namespace dynamap::app::gui
