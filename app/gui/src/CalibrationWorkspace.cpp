#include "dynamap/app/gui/CalibrationWorkspace.hpp"

#include <QCheckBox>
#include <QComboBox>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QProgressBar>
#include <QPushButton>
#include <QScrollArea>
#include <QSpinBox>
#include <QSplitter>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>
#include <cmath>

#include "dynamap/app/gui/CalibrationResults.hpp"
#include "dynamap/app/gui/DepthPreview.hpp"
#include "dynamap/app/gui/ResourceFiles.hpp"

namespace dynamap::app::gui {

namespace cal = calibration;

namespace {

constexpr cal::SessionStep kSteps[] = {cal::SessionStep::kFloor, cal::SessionStep::kTurn,
                                       cal::SessionStep::kStraight, cal::SessionStep::kArcs,
                                       cal::SessionStep::kSolve, cal::SessionStep::kReview,
                                       cal::SessionStep::kSave};

QString JoinCounts(const std::vector<int>& counts) {
  QStringList parts;
  for (int c : counts) parts << QString::number(c);
  return parts.isEmpty() ? QStringLiteral("–") : parts.join(QStringLiteral(" / "));
}

}  // namespace

CalibrationWorkspace::CalibrationWorkspace(QWidget* parent) : QWidget(parent) {
  start_task_ = new BackgroundTask(this);
  auto* panel = new QWidget;
  auto* panel_layout = new QVBoxLayout(panel);
  panel_layout->addWidget(MakeSetupGroup());
  panel_layout->addWidget(MakeWizardGroup());
  panel_layout->addWidget(MakeDriveGroup());
  panel_layout->addStretch(1);
  auto* scroll = new QScrollArea;
  scroll->setWidget(panel);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  scroll->setMinimumWidth(440);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);

  depth0_ = new DepthPreview(tr("Kinect 0"));
  depth1_ = new DepthPreview(tr("Kinect 1"));
  results_ = new CalibrationResults;
  auto* depth_row = new QSplitter(Qt::Horizontal);
  depth_row->addWidget(depth0_);
  depth_row->addWidget(depth1_);
  auto* right = new QSplitter(Qt::Vertical);
  right->addWidget(depth_row);
  right->addWidget(results_);
  right->setStretchFactor(0, 1);
  right->setStretchFactor(1, 1);
  auto* splitter = new QSplitter(Qt::Horizontal);
  splitter->addWidget(scroll);
  splitter->addWidget(right);
  splitter->setStretchFactor(1, 1);
  splitter->setSizes({450, 1000});
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(splitter);

  poll_timer_.setInterval(200);
  connect(&poll_timer_, &QTimer::timeout, this, &CalibrationWorkspace::Refresh);
  out_dir_ = QDir::home().filePath(QStringLiteral("dynamap-calibration"));
  ShowSource();
  ShowState();
}

CalibrationWorkspace::~CalibrationWorkspace() = default;

QWidget* CalibrationWorkspace::MakeSetupGroup() {
  setup_ = new QGroupBox(tr("Session"));
  auto* form = new QFormLayout(setup_);
  setup_form_ = form;
  source_ = new QComboBox;
  source_->setObjectName(QStringLiteral("calibration_source"));
  source_->addItem(tr("Simulator"));
  source_->addItem(tr("Recording"));
  source_->setToolTip(tr("Drive the guided sequence in the simulator, or replay a recording "
                         "of it made on the robot (dynamap record --device)"));
  form->addRow(tr("Source"), source_);
  recording_ = new QLineEdit;
  recording_->setObjectName(QStringLiteral("calibration_recording"));
  recording_->setPlaceholderText(tr("recording folder of the guided sequence"));
  recording_row_ = new QWidget;
  auto* recording_layout = new QHBoxLayout(recording_row_);
  recording_layout->setContentsMargins(0, 0, 0, 0);
  recording_layout->addWidget(recording_, 1);
  auto* browse = new QToolButton;
  browse->setText(QStringLiteral("…"));
  browse->setToolTip(tr("Choose a recording folder"));
  connect(browse, &QToolButton::clicked, this, [this] {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Choose a recording folder"),
                                                          recording_->text());
    if (!dir.isEmpty()) recording_->setText(dir);
  });
  recording_layout->addWidget(browse);
  form->addRow(tr("Recording"), recording_row_);
  world_ = new QComboBox;
  for (const QString& file : ResourceFiles(QStringLiteral("worlds"))) {
    world_->addItem(QFileInfo(file).fileName(), file);
  }
  world_->setCurrentIndex(std::max(0, world_->findText(QStringLiteral("calibration_room.yaml"))));
  form->addRow(tr("Room"), world_);
  rig_ = new QComboBox;
  for (const QString& file : ResourceFiles(QStringLiteral("rigs"))) {
    rig_->addItem(QFileInfo(file).fileName(), file);
  }
  rig_->setCurrentIndex(std::max(0, rig_->findText(QStringLiteral("two_kinects_guess.yaml"))));
  rig_->setToolTip(tr("The measured guess the calibration starts from"));
  form->addRow(tr("Rig guess"), rig_);
  seed_ = new QSpinBox;
  seed_->setRange(1, 1000000);
  seed_->setToolTip(tr("Chooses the simulated true rig (the guess moved by up to 10° and "
                       "10 cm per axis) and the sensor noise"));
  form->addRow(tr("Seed"), seed_);
  width_ = new QComboBox;
  for (int w : {160, 320, 640}) width_->addItem(QStringLiteral("%1 px").arg(w), w);
  width_->setCurrentIndex(1);
  form->addRow(tr("Depth width"), width_);
  pace_ = new QComboBox;
  pace_->addItem(tr("Real time"), 1.0);
  pace_->addItem(tr("As fast as possible"), 0.0);
  form->addRow(tr("Pace"), pace_);
  connect(source_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this] { ShowSource(); });
  begin_ = new QPushButton(style()->standardIcon(QStyle::SP_MediaPlay), tr("Begin session"));
  begin_->setObjectName(QStringLiteral("calibration_begin"));
  connect(begin_, &QPushButton::clicked, this, [this] {
    if (HasSession()) {
      EndSession();
    } else {
      BeginSession(BuildSetup());
    }
  });
  form->addRow(begin_);
  return setup_;
}

QWidget* CalibrationWorkspace::MakeWizardGroup() {
  auto* box = new QGroupBox(tr("Guided calibration"));
  auto* layout = new QVBoxLayout(box);
  steps_ = new QListWidget;
  steps_->setFlow(QListView::LeftToRight);
  steps_->setFixedHeight(34);
  steps_->setSelectionMode(QAbstractItemView::NoSelection);
  steps_->setFocusPolicy(Qt::NoFocus);
  for (cal::SessionStep step : kSteps) steps_->addItem(QString::fromLatin1(cal::SessionStepName(step)));
  layout->addWidget(steps_);
  instruction_ = new QLabel;
  instruction_->setWordWrap(true);
  QFont big = instruction_->font();
  big.setPointSizeF(big.pointSizeF() * 1.25);
  big.setBold(true);
  instruction_->setFont(big);
  layout->addWidget(instruction_);
  step_progress_ = new QProgressBar;
  step_progress_->setRange(0, 100);
  layout->addWidget(step_progress_);
  detail_ = new QLabel;
  detail_->setWordWrap(true);
  layout->addWidget(detail_);
  counters_ = new QLabel;
  counters_->setWordWrap(true);
  counters_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  layout->addWidget(counters_);

  next_ = new QPushButton(tr("Next step"));
  next_->setShortcut(Qt::CTRL | Qt::Key_Return);
  next_->setToolTip(tr("Go on when the step is complete (Ctrl+Enter)"));
  skip_ = new QPushButton(tr("Skip"));
  skip_->setToolTip(tr("Leave the step incomplete; the solver will say what that costs"));
  solve_ = new QPushButton(tr("Solve"));
  solve_->setToolTip(tr("Run the joint refinement on what was captured"));
  auto* row = new QHBoxLayout;
  row->addWidget(next_);
  row->addWidget(skip_);
  row->addWidget(solve_);
  layout->addLayout(row);
  redo_ = new QComboBox;
  redo_->addItem(tr("Redo a step…"));
  for (int i = 0; i < 4; ++i) redo_->addItem(QString::fromLatin1(cal::SessionStepName(kSteps[i])));
  save_ = new QPushButton(style()->standardIcon(QStyle::SP_DialogSaveButton), tr("Save rig…"));
  allow_uncalibrated_ = new QCheckBox(tr("save uncalibrated"));
  allow_uncalibrated_->setToolTip(tr("Write the rig even when some parameters are weak or not "
                                     "observable (they keep their guessed or weak values)"));
  auto* row2 = new QHBoxLayout;
  row2->addWidget(redo_);
  row2->addWidget(save_);
  row2->addWidget(allow_uncalibrated_);
  layout->addLayout(row2);
  connect(next_, &QPushButton::clicked, this, &CalibrationWorkspace::Next);
  connect(skip_, &QPushButton::clicked, this, &CalibrationWorkspace::SkipStep);
  connect(solve_, &QPushButton::clicked, this, &CalibrationWorkspace::Solve);
  connect(save_, &QPushButton::clicked, this, &CalibrationWorkspace::SaveWithDialog);
  connect(redo_, QOverload<int>::of(&QComboBox::activated), this, [this](int index) {
    if (index > 0 && run_) run_->Redo(kSteps[index - 1]);
    redo_->setCurrentIndex(0);
  });
  return box;
}

QWidget* CalibrationWorkspace::MakeDriveGroup() {
  drive_ = new QGroupBox(tr("Drive the robot"));
  auto* grid = new QGridLayout(drive_);
  struct Command {
    QString label;
    double v, omega;
    int row, column;
    Qt::Key key;
  };
  const Command commands[] = {
      {tr("Arc left"), 0.3, 0.4, 0, 0, Qt::Key_Q},  {tr("Forward"), 0.3, 0.0, 0, 1, Qt::Key_W},
      {tr("Arc right"), 0.3, -0.4, 0, 2, Qt::Key_E}, {tr("Turn left"), 0.0, 0.5, 1, 0, Qt::Key_A},
      {tr("Stop"), 0.0, 0.0, 1, 1, Qt::Key_S},       {tr("Turn right"), 0.0, -0.5, 1, 2, Qt::Key_D},
      {tr("Back arc"), -0.3, -0.4, 2, 0, Qt::Key_Z}, {tr("Back"), -0.3, 0.0, 2, 1, Qt::Key_X}};
  for (const Command& c : commands) {
    auto* button = new QPushButton(c.label);
    button->setShortcut(c.key);
    button->setToolTip(tr("v %1 m/s, ω %2 rad/s (%3)")
                           .arg(c.v)
                           .arg(c.omega)
                           .arg(QKeySequence(c.key).toString(QKeySequence::NativeText)));
    const double v = c.v, omega = c.omega;
    connect(button, &QPushButton::clicked, this, [this, v, omega] {
      if (run_) run_->Drive(v, omega);
    });
    grid->addWidget(button, c.row, c.column);
  }
  auto_drive_ = new QPushButton(tr("Drive this step for me"));
  auto_drive_->setObjectName(QStringLiteral("calibration_drive_step"));
  auto_drive_->setToolTip(tr("The motions the step asks for, stopping when it is complete"));
  connect(auto_drive_, &QPushButton::clicked, this, &CalibrationWorkspace::DriveStep);
  grid->addWidget(auto_drive_, 3, 0, 1, 3);
  return drive_;
}

std::vector<QWidget*> CalibrationWorkspace::SetupFields() const {
  return {source_, recording_row_, world_, rig_, seed_, width_, pace_};
}

bool CalibrationWorkspace::ReplaysRecording() const { return source_->currentIndex() == 1; }

void CalibrationWorkspace::ShowSource() {
  const bool replay = ReplaysRecording();
  const auto show_row = [this](QWidget* field, bool visible) {
    field->setVisible(visible);
    if (QWidget* label = setup_form_->labelForField(field)) label->setVisible(visible);
  };
  show_row(recording_row_, replay);
  // The room, the simulated rig's seed and the image width belong to the simulator.
  show_row(world_, !replay);
  show_row(seed_, !replay);
  show_row(width_, !replay);
}

void CalibrationWorkspace::SetRecording(const QString& dir) {
  source_->setCurrentIndex(1);
  recording_->setText(dir);
}

CalibrationSetup CalibrationWorkspace::BuildSetup() const {
  CalibrationSetup setup;
  if (ReplaysRecording()) setup.recording_dir = recording_->text().trimmed().toStdString();
  setup.world_file = world_->currentData().toString().toStdString();
  setup.rig_guess_file = rig_->currentData().toString().toStdString();
  setup.robot_file = ResourcePath(QStringLiteral("robots/segway_rmp50.yaml")).toStdString();
  setup.seed = static_cast<std::uint64_t>(seed_->value());
  setup.width = width_->currentData().toInt();
  setup.speed = pace_->currentData().toDouble();
  setup.out_dir =
      QDir(out_dir_)
          .filePath(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss")))
          .toStdString();
  return setup;
}

void CalibrationWorkspace::BeginSession(const CalibrationSetup& setup) {
  EndSession();
  setup_->setEnabled(false);
  emit StatusMessage(tr("Starting the calibration session…"));
  start_task_->Start(tr("Starting calibration"), [this, setup](const BackgroundTask::Context& c) {
    auto run = CalibrationRun::Create(setup);
    if (!run) {
      const QString message = QString::fromStdString(run.error().message);
      c.Deliver([this, message] {
        setup_->setEnabled(true);
        last_message_ = message;
        emit ErrorOccurred(message);
      });
      return;
    }
    std::shared_ptr<CalibrationRun> shared = std::move(run).value();
    c.Deliver([this, shared] {
      run_ = shared;
      results_->Clear();
      shown_result_ = nullptr;
      shown_plots_ = 0;
      seen_message_ = 0;
      last_message_.clear();
      begin_->setText(tr("End session"));
      begin_->setIcon(style()->standardIcon(QStyle::SP_MediaStop));
      setup_->setEnabled(true);
      for (QWidget* w : SetupFields()) w->setEnabled(false);
      poll_timer_.start();
      Refresh();
      emit SessionStarted();
    });
  });
}

void CalibrationWorkspace::EndSession() {
  start_task_->Cancel();
  poll_timer_.stop();
  run_.reset();  // Stops the simulator thread (it leaves within one 50 ms step).
  state_ = CalibrationState();
  begin_->setText(tr("Begin session"));
  begin_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
  setup_->setEnabled(true);
  for (QWidget* w : SetupFields()) w->setEnabled(true);
  depth0_->Clear();
  depth1_->Clear();
  ShowState();
}

void CalibrationWorkspace::SetWorldFile(const QString& file) {
  source_->setCurrentIndex(0);
  const QString path = QFileInfo(file).absoluteFilePath();
  int index = world_->findData(path);
  if (index < 0) {
    world_->addItem(QFileInfo(file).fileName(), path);
    index = world_->count() - 1;
  }
  world_->setCurrentIndex(index);
}

void CalibrationWorkspace::SetOutputDir(const QString& dir) { out_dir_ = dir; }

void CalibrationWorkspace::SetImageWidth(int width) {
  const int index = width_->findData(width);
  if (index >= 0) width_->setCurrentIndex(index);
}

void CalibrationWorkspace::SetSpeed(double speed) {
  const int index = pace_->findData(speed);
  if (index >= 0) pace_->setCurrentIndex(index);
}

void CalibrationWorkspace::DriveStep() {
  if (run_) run_->DriveCurrentStep();
}

void CalibrationWorkspace::Next() {
  if (run_) run_->Advance();
}

void CalibrationWorkspace::SkipStep() {
  if (run_) run_->Skip();
}

void CalibrationWorkspace::Solve() {
  if (!run_) return;
  run_->Solve();
  emit StatusMessage(tr("Solving the rig…"));
  Refresh();
}

void CalibrationWorkspace::SaveTo(const QString& file) {
  if (run_) run_->Save(file.toStdString(), allow_uncalibrated_->isChecked());
}

void CalibrationWorkspace::SaveWithDialog() {
  if (!run_) return;
  QString file = QFileDialog::getSaveFileName(
      this, tr("Save calibrated rig"),
      QDir(QString::fromStdString(run_->Setup().out_dir)).filePath(QStringLiteral("rig.yaml")),
      tr("Rig files (*.yaml)"));
  if (file.isEmpty()) return;
  if (QFileInfo(file).suffix().isEmpty()) file += QStringLiteral(".yaml");
  SaveTo(file);
}

void CalibrationWorkspace::Refresh() {
  if (!run_) return;
  const std::string saved_before = state_.saved_file;
  state_ = run_->State();
  if (state_.message_serial != seen_message_) {
    seen_message_ = state_.message_serial;
    last_message_ = QString::fromStdString(state_.message);
    emit StatusMessage(last_message_);
  }
  if (state_.saved_file != saved_before && !state_.saved_file.empty()) {
    emit StatusMessage(tr("Saved the calibrated rig to %1")
                           .arg(QString::fromStdString(state_.saved_file)));
  }
  ShowState();
}

void CalibrationWorkspace::ShowState() {
  const bool session = run_ != nullptr;
  const cal::SessionProgress& p = state_.progress;
  const bool capturing = session && static_cast<int>(p.step) <= static_cast<int>(cal::SessionStep::kArcs);
  const bool reviewing = session && (p.step == cal::SessionStep::kReview ||
                                     p.step == cal::SessionStep::kSave);
  for (int i = 0; i < steps_->count(); ++i) {
    QListWidgetItem* item = steps_->item(i);
    const bool current = session && kSteps[i] == p.step;
    const bool done = session && static_cast<int>(kSteps[i]) < static_cast<int>(p.step);
    QFont font = item->font();
    font.setBold(current);
    item->setFont(font);
    item->setForeground(current ? palette().highlight() : (done ? palette().text() : palette().mid()));
    item->setText(QString::fromLatin1(cal::SessionStepName(kSteps[i])) +
                  (done ? QStringLiteral(" ✓") : QString()));
  }
  if (!session) {
    instruction_->setText(Starting() ? tr("Starting the session…")
                                     : ReplaysRecording()
                                           ? tr("Choose the recording and the rig guess, then begin.")
                                           : tr("Choose the room and the rig guess, then begin."));
    detail_->clear();
    counters_->clear();
    step_progress_->setValue(0);
  } else if (state_.solving) {
    instruction_->setText(tr("Solving: joint refinement of both mounts, latencies and wheel scales…"));
  } else {
    instruction_->setText(QString::fromStdString(p.instruction));
    detail_->setText(QString::fromStdString(p.detail));
    step_progress_->setValue(static_cast<int>(std::lround(100.0 * p.fraction)));
    QStringList inlier;
    for (const auto& fit : state_.floor) {
      inlier << (fit ? QStringLiteral("%1 %").arg(100.0 * fit->inlier_share, 0, 'f', 0)
                     : QStringLiteral("–"));
    }
    counters_->setText(
        tr("Floor fits %1 (last inlier share %2)<br>"
           "Turned %3° left, %4° right<br>Straight %5 m forward, %6 m back<br>"
           "Arcs %7 m left, %8 m right<br>ICP pairs this step %9, rejected %10<br>"
           "%11 %12 s%13")
            .arg(JoinCounts(p.floor_fits), inlier.join(QStringLiteral(" / ")))
            .arg(p.turned_left_deg, 0, 'f', 0)
            .arg(p.turned_right_deg, 0, 'f', 0)
            .arg(p.forward_m, 0, 'f', 2)
            .arg(p.backward_m, 0, 'f', 2)
            .arg(p.arc_left_m, 0, 'f', 2)
            .arg(p.arc_right_m, 0, 'f', 2)
            .arg(JoinCounts(p.step_pairs), JoinCounts(p.rejected_pairs))
            .arg(state_.replay ? tr("Replayed %1 % of the recording,")
                                     .arg(100.0 * state_.replay_fraction, 0, 'f', 0)
                               : tr("Simulated"))
            .arg(state_.sim_time_s, 0, 'f', 1)
            .arg(state_.collisions > 0 ? tr(", %1 collisions").arg(state_.collisions) : QString()));
  }
  drive_->setEnabled(capturing && !state_.solving && !state_.replay);
  auto_drive_->setEnabled(capturing && !state_.auto_driving && !state_.replay);
  next_->setEnabled(capturing && p.complete);
  skip_->setEnabled(capturing);
  solve_->setEnabled(session && !state_.solving && !reviewing &&
                     p.step != cal::SessionStep::kDone);
  // A recording cannot be extended: a weak step is recorded again and replayed.
  redo_->setEnabled(reviewing && !state_.replay);
  redo_->setToolTip(state_.replay ? tr("A replayed recording cannot be extended: record the "
                                       "step again and replay the new recording")
                                  : tr("Capture a step again and solve with the new data"));
  save_->setEnabled(reviewing && !state_.solving);

  for (std::size_t k = 0; k < state_.depth.size() && k < 2 && session; ++k) {
    const robotio::DepthFrame& frame = state_.depth[k];
    if (!frame.Valid()) continue;
    DepthImageOptions options;
    const auto& mount = run_->Guess().kinects.at(k);
    options.rotate_180 = std::abs(robotio::MountRollPitchYaw(mount.T_base_kinect).x()) > M_PI / 2;
    options.max_range_m = mount.max_range_m;
    if (k < state_.floor.size() && state_.floor[k] && state_.floor[k]->ok) {
      options.plane = DepthPlane{state_.floor[k]->normal, state_.floor[k]->distance_m, 0.03};
    }
    (k == 0 ? depth0_ : depth1_)->SetFrame(frame, options);
  }
  if (session && state_.result && state_.result.get() != shown_result_) {
    shown_result_ = state_.result.get();
    results_->Show(*state_.result, run_->Guess(), run_->Truth(), run_->TrueScaleLeft(),
                   run_->TrueScaleRight(), run_->RobotRadius());
  }
  if (session && state_.plots.size() != shown_plots_) {
    shown_plots_ = state_.plots.size();
    results_->ShowPlots(state_.plots);
  }
}

}  // namespace dynamap::app::gui
