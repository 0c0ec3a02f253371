#include "dynamap/app/gui/MainWindow.hpp"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCloseEvent>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QStyle>
#include <QToolBar>
#include <vtkVersion.h>

#include "dynamap/app/Version.hpp"
#include "dynamap/app/gui/CalibrationWorkspace.hpp"
#include "dynamap/app/gui/MapControls.hpp"
#include "dynamap/app/gui/MapsWorkspace.hpp"
#include "dynamap/app/gui/MissionWorkspace.hpp"
#include "dynamap/app/gui/StatusPanel.hpp"
#include "dynamap/app/gui/VoxelView.hpp"

namespace dynamap::app::gui {

namespace {

constexpr int kStatusMessageMs = 8000;
QString MapFileFilter() {
  return QObject::tr("Maps (*.ot *.bt);;Dual maps (*.ot);;OctoMap (*.bt);;All files (*)");
}

QAction* MakeAction(QObject* parent, const QString& name, const QString& text,
                    const QKeySequence& shortcut, const QString& tip) {
  auto* action = new QAction(text, parent);
  action->setObjectName(name);
  action->setShortcut(shortcut);
  action->setStatusTip(tip);
  action->setToolTip(shortcut.isEmpty()
                         ? tip
                         : QStringLiteral("%1 (%2)").arg(tip, shortcut.toString(
                                                                  QKeySequence::NativeText)));
  return action;
}

}  // namespace

MainWindow::MainWindow(QWidget* parent) : QMainWindow(parent) {
  setWindowTitle(QStringLiteral("dynamap"));
  sidebar_ = new QListWidget;
  sidebar_->setObjectName(QStringLiteral("workspace_sidebar"));
  sidebar_->setFixedWidth(110);
  sidebar_->setSpacing(2);
  sidebar_->setStyleSheet(QStringLiteral(
      "QListWidget { background: palette(window); border: none; font-weight: bold; }"
      "QListWidget::item { padding: 10px 8px; border-radius: 4px; }"
      "QListWidget::item:selected { background: palette(highlight); "
      "color: palette(highlighted-text); }"));
  stack_ = new QStackedWidget;
  auto* central = new QWidget;
  auto* layout = new QHBoxLayout(central);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(0);
  layout->addWidget(sidebar_);
  layout->addWidget(stack_, 1);
  setCentralWidget(central);
  connect(sidebar_, &QListWidget::currentRowChanged, stack_, &QStackedWidget::setCurrentIndex);

  calibration_ = new CalibrationWorkspace;
  AddWorkspace(calibration_, tr("Calibration"),
               tr("Calibrate the Kinect rig with the guided session"));
  mission_ = new MissionWorkspace;
  AddWorkspace(mission_, tr("Mission"),
               tr("Explore a simulated world, or replay a recording, and watch the maps grow"));
  maps_ = new MapsWorkspace;
  AddWorkspace(maps_, tr("Maps"), tr("Open, inspect and export saved maps"));

  status_panel_ = new StatusPanel;
  statusBar()->addPermanentWidget(status_panel_);
  connect(mission_, &MissionWorkspace::StatusChanged, this,
          [this](const QString& state, std::optional<std::uint64_t> dropped) {
            const auto& config = mission_->Session()->Config();
            status_panel_->SetConnection(
                !config.recording_dir.empty() ? RobotConnection::kRecording
                : config.world_file.empty()   ? RobotConnection::kHardware
                                              : RobotConnection::kSimulator);
            status_panel_->SetMissionState(state);
            status_panel_->SetDroppedFrames(dropped);
          });
  connect(mission_, &MissionWorkspace::ErrorOccurred, this, &MainWindow::ShowError);
  connect(calibration_, &CalibrationWorkspace::ErrorOccurred, this, &MainWindow::ShowError);
  connect(calibration_, &CalibrationWorkspace::StatusMessage, this,
          [this](const QString& message) { statusBar()->showMessage(message, kStatusMessageMs); });
  connect(calibration_, &CalibrationWorkspace::SessionStarted, this, [this] {
    status_panel_->SetConnection(calibration_->ReplaysRecording() ? RobotConnection::kRecording
                                                                  : RobotConnection::kSimulator);
  });

  CreateActions();
  CreateMenus();
  CreateToolBar();

  connect(maps_, &MapsWorkspace::StatusMessage, this,
          [this](const QString& message) { statusBar()->showMessage(message, kStatusMessageMs); });
  connect(maps_, &MapsWorkspace::ErrorOccurred, this, &MainWindow::ShowError);
  connect(maps_, &MapsWorkspace::MapOpened, this, [this](const QString& file) {
    recent_.Add(file);
    RebuildRecentMenu();
    setWindowTitle(QStringLiteral("%1 — dynamap").arg(QFileInfo(file).fileName()));
    UpdateActionStates();
    SyncLayerActions();
  });
  connect(maps_, &MapsWorkspace::BusyChanged, this, [this] { UpdateActionStates(); });
  connect(maps_->Controls(), &MapControls::FilterChanged, this, &MainWindow::SyncLayerActions);
  connect(maps_->Controls(), &MapControls::ColourModeChanged, this,
          &MainWindow::SyncLayerActions);

  RestoreSettings();
  RebuildRecentMenu();
  UpdateActionStates();
}

MainWindow::~MainWindow() = default;

void MainWindow::OpenMap(const QString& file) {
  ShowWorkspace(stack_->indexOf(maps_));
  maps_->OpenFile(file);
}

bool MainWindow::Explore(const ExploreRequest& request) {
  ShowWorkspace(stack_->indexOf(mission_));
  return mission_->Explore(request);
}

QStringList MainWindow::WorkspaceNames() const {
  QStringList names;
  for (int i = 0; i < sidebar_->count(); ++i) names << sidebar_->item(i)->text();
  return names;
}

int MainWindow::CurrentWorkspace() const { return stack_->currentIndex(); }

void MainWindow::ShowWorkspace(int index) {
  if (index >= 0 && index < sidebar_->count()) sidebar_->setCurrentRow(index);
}

QAction* MainWindow::FindAction(const QString& object_name) const {
  return findChild<QAction*>(object_name);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  maps_->CancelWork();
  mission_->StopMission();
  calibration_->EndSession();
  SaveSettings();
  event->accept();
}

void MainWindow::AddWorkspace(QWidget* workspace, const QString& name, const QString& tip) {
  stack_->addWidget(workspace);
  auto* item = new QListWidgetItem(name, sidebar_);
  item->setToolTip(tip);
  item->setTextAlignment(Qt::AlignCenter);
  if (sidebar_->currentRow() < 0) sidebar_->setCurrentRow(0);
}

void MainWindow::CreateActions() {
  QStyle* s = style();
  open_action_ = MakeAction(this, QStringLiteral("open_map"), tr("&Open map…"),
                            QKeySequence::Open, tr("Open a dual map (.ot) or an OctoMap (.bt)"));
  open_action_->setIcon(s->standardIcon(QStyle::SP_DialogOpenButton));
  connect(open_action_, &QAction::triggered, this, &MainWindow::OpenMapWithDialog);

  for (const ExportFormat& format : ExportFormats()) {
    auto* action = MakeAction(this, QStringLiteral("export_%1").arg(static_cast<int>(format.kind)),
                              tr(format.label), QKeySequence(), tr(format.label));
    const ExportKind kind = format.kind;
    connect(action, &QAction::triggered, this, [this, kind] { ExportWithDialog(kind); });
    export_actions_.push_back(action);
  }
  export_actions_.front()->setShortcut(QKeySequence(Qt::CTRL | Qt::Key_E));
  save_view_action_ = MakeAction(this, QStringLiteral("save_view"), tr("Save 3D &view as PNG…"),
                                 QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S),
                                 tr("Save what the 3D view shows"));
  save_view_action_->setIcon(s->standardIcon(QStyle::SP_DialogSaveButton));
  connect(save_view_action_, &QAction::triggered, this, &MainWindow::SaveViewWithDialog);
  quit_action_ = MakeAction(this, QStringLiteral("quit"), tr("&Quit"), QKeySequence::Quit,
                            tr("Close dynamap"));
  connect(quit_action_, &QAction::triggered, this, &QWidget::close);

  static_action_ = MakeAction(this, QStringLiteral("show_static"), tr("&Static map"),
                              QKeySequence(Qt::Key_F5), tr("Show the static map"));
  dynamic_action_ = MakeAction(this, QStringLiteral("show_dynamic"), tr("&Dynamic map"),
                               QKeySequence(Qt::Key_F6), tr("Show the dynamic map (red)"));
  for (QAction* action : {static_action_, dynamic_action_}) {
    action->setCheckable(true);
    action->setChecked(true);
  }
  connect(static_action_, &QAction::toggled, maps_->Controls(), &MapControls::SetShowStatic);
  connect(dynamic_action_, &QAction::toggled, maps_->Controls(), &MapControls::SetShowDynamic);

  colour_height_action_ = MakeAction(this, QStringLiteral("colour_height"),
                                     tr("Colour by &height"), QKeySequence(Qt::Key_F7),
                                     tr("Colour static voxels by height"));
  colour_occupancy_action_ = MakeAction(this, QStringLiteral("colour_occupancy"),
                                        tr("Colour by &occupancy"), QKeySequence(Qt::Key_F8),
                                        tr("Colour static voxels by occupancy probability"));
  auto* colour_group = new QActionGroup(this);
  for (QAction* action : {colour_height_action_, colour_occupancy_action_}) {
    action->setCheckable(true);
    colour_group->addAction(action);
  }
  colour_height_action_->setChecked(true);
  connect(colour_height_action_, &QAction::triggered, this,
          [this] { maps_->Controls()->SetColourMode(ColourMode::kHeight); });
  connect(colour_occupancy_action_, &QAction::triggered, this,
          [this] { maps_->Controls()->SetColourMode(ColourMode::kOccupancy); });

  reset_camera_action_ = MakeAction(this, QStringLiteral("reset_camera"), tr("&Reset camera"),
                                    QKeySequence(Qt::CTRL | Qt::Key_R),
                                    tr("Frame the whole map"));
  reset_camera_action_->setIcon(s->standardIcon(QStyle::SP_BrowserReload));
  connect(reset_camera_action_, &QAction::triggered, this, [this] { maps_->View()->ResetCamera(); });
  cancel_action_ = MakeAction(this, QStringLiteral("cancel_work"), tr("&Cancel loading"),
                              QKeySequence(), tr("Stop the running load or export"));
  cancel_action_->setIcon(s->standardIcon(QStyle::SP_BrowserStop));
  connect(cancel_action_, &QAction::triggered, maps_, &MapsWorkspace::CancelWork);

  about_action_ = MakeAction(this, QStringLiteral("about"), tr("&About dynamap"),
                             QKeySequence(Qt::Key_F1), tr("Version and components"));
  connect(about_action_, &QAction::triggered, this, &MainWindow::ShowAbout);
}

void MainWindow::CreateMenus() {
  QMenu* file = menuBar()->addMenu(tr("&File"));
  file->addAction(open_action_);
  recent_menu_ = file->addMenu(tr("Open &recent"));
  export_menu_ = file->addMenu(tr("&Export"));
  for (QAction* action : export_actions_) export_menu_->addAction(action);
  file->addAction(save_view_action_);
  file->addSeparator();
  file->addAction(quit_action_);

  QMenu* view = menuBar()->addMenu(tr("&View"));
  for (int i = 0; i < sidebar_->count(); ++i) {
    auto* action = MakeAction(this, QStringLiteral("workspace_%1").arg(i),
                              tr("%1 workspace").arg(sidebar_->item(i)->text()),
                              QKeySequence(Qt::CTRL | (Qt::Key_1 + i)),
                              sidebar_->item(i)->toolTip());
    connect(action, &QAction::triggered, this, [this, i] { ShowWorkspace(i); });
    view->addAction(action);
    workspace_actions_.push_back(action);
  }
  view->addSeparator();
  view->addAction(static_action_);
  view->addAction(dynamic_action_);
  view->addSeparator();
  view->addAction(colour_height_action_);
  view->addAction(colour_occupancy_action_);
  view->addSeparator();
  view->addAction(reset_camera_action_);

  QMenu* help = menuBar()->addMenu(tr("&Help"));
  help->addAction(about_action_);
}

void MainWindow::CreateToolBar() {
  QToolBar* bar = addToolBar(tr("Main"));
  bar->setObjectName(QStringLiteral("main_toolbar"));
  bar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  bar->setMovable(false);
  bar->addAction(open_action_);
  bar->addAction(export_menu_->menuAction());
  export_menu_->menuAction()->setIcon(style()->standardIcon(QStyle::SP_DialogSaveButton));
  bar->addSeparator();
  bar->addAction(static_action_);
  bar->addAction(dynamic_action_);
  bar->addAction(colour_height_action_);
  bar->addAction(colour_occupancy_action_);
  bar->addAction(reset_camera_action_);
  bar->addSeparator();
  bar->addAction(cancel_action_);
}

void MainWindow::RestoreSettings() {
  QSettings settings;
  recent_.Load(settings);
  if (!restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray())) {
    resize(1440, 900);
  }
  restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
  ShowWorkspace(settings.value(QStringLiteral("window/workspace"), 0).toInt());
}

void MainWindow::SaveSettings() const {
  QSettings settings;
  recent_.Save(settings);
  settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
  settings.setValue(QStringLiteral("window/state"), saveState());
  settings.setValue(QStringLiteral("window/workspace"), CurrentWorkspace());
}

void MainWindow::RebuildRecentMenu() {
  recent_menu_->clear();
  int number = 1;
  for (const QString& file : recent_.Files()) {
    QAction* action = recent_menu_->addAction(
        QStringLiteral("&%1  %2").arg(number++).arg(QFileInfo(file).fileName()));
    action->setToolTip(file);
    action->setStatusTip(file);
    connect(action, &QAction::triggered, this, [this, file] { OpenMap(file); });
  }
  recent_menu_->setEnabled(!recent_.Files().isEmpty());
  QSettings settings;
  recent_.Save(settings);
}

void MainWindow::UpdateActionStates() {
  const bool busy = maps_->Busy();
  const bool has_map = maps_->Map() != nullptr;
  for (QAction* action : export_actions_) action->setEnabled(has_map && !busy);
  export_menu_->setEnabled(has_map && !busy);
  save_view_action_->setEnabled(has_map);
  cancel_action_->setEnabled(busy);
  dynamic_action_->setEnabled(has_map && maps_->Controls()->DynamicAvailable());
}

void MainWindow::SyncLayerActions() {
  const VoxelFilter filter = maps_->Controls()->Filter();
  const QSignalBlocker block_static(static_action_);
  const QSignalBlocker block_dynamic(dynamic_action_);
  static_action_->setChecked(filter.show_static);
  dynamic_action_->setChecked(filter.show_dynamic || !maps_->Controls()->DynamicAvailable());
  const bool by_height = maps_->Controls()->Colours() == ColourMode::kHeight;
  colour_height_action_->setChecked(by_height);
  colour_occupancy_action_->setChecked(!by_height);
  dynamic_action_->setEnabled(maps_->Map() != nullptr && maps_->Controls()->DynamicAvailable());
}

void MainWindow::OpenMapWithDialog() {
  const QString file = QFileDialog::getOpenFileName(this, tr("Open map"), LastDirectory(),
                                                    MapFileFilter());
  if (file.isEmpty()) return;
  RememberDirectory(file);
  OpenMap(file);
}

void MainWindow::ExportWithDialog(ExportKind kind) {
  const ExportFormat& format = FormatOf(kind);
  QString file = QFileDialog::getSaveFileName(this, tr(format.label), LastDirectory(),
                                              tr(format.filter));
  if (file.isEmpty()) return;
  if (QFileInfo(file).suffix().isEmpty()) file += QStringLiteral(".") + format.suffix;
  RememberDirectory(file);
  maps_->Export(kind, file);
}

void MainWindow::SaveViewWithDialog() {
  QString file = QFileDialog::getSaveFileName(this, tr("Save 3D view"), LastDirectory(),
                                              tr("PNG image (*.png)"));
  if (file.isEmpty()) return;
  if (QFileInfo(file).suffix().isEmpty()) file += QStringLiteral(".png");
  RememberDirectory(file);
  maps_->SaveViewImage(file);
}

void MainWindow::ShowAbout() {
  QMessageBox::about(
      this, tr("About dynamap"),
      tr("<h3>dynamap %1</h3>"
         "<p>Autonomous 3D mapping of dynamic indoor scenes: Kinect rig calibration, "
         "exploration with a static and a dynamic OctoMap, map inspection and export.</p>"
         "<p>Qt %2, VTK %3</p>")
          .arg(QStringLiteral(DYNAMAP_VERSION_STRING), QString::fromLatin1(qVersion()),
               QString::fromLatin1(vtkVersion::GetVTKVersion())));
}

void MainWindow::ShowError(const QString& message) {
  // Window-modal but not blocking: the event loop (and running work) carries on.
  auto* box = new QMessageBox(QMessageBox::Warning, tr("dynamap"), message, QMessageBox::Ok,
                              this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open();
}

QString MainWindow::LastDirectory() const {
  return QSettings().value(QStringLiteral("dialogs/last_directory"), QDir::homePath()).toString();
}

void MainWindow::RememberDirectory(const QString& file) {
  QSettings().setValue(QStringLiteral("dialogs/last_directory"),
                       QFileInfo(file).absolutePath());
}

}  // namespace dynamap::app::gui
