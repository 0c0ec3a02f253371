// The application window: a side bar of workspaces, menus and toolbar with shortcuts, the
// status bar, file dialogs, recent files and window layout kept in QSettings.
#pragma once

#include <QMainWindow>
#include <QString>
#include <vector>

#include "dynamap/app/gui/MapExportFormats.hpp"
#include "dynamap/app/gui/RecentFiles.hpp"

class QAction;
class QActionGroup;
class QListWidget;
class QMenu;
class QStackedWidget;

namespace dynamap::app::gui {

class CalibrationWorkspace;
class MapsWorkspace;
class MissionWorkspace;
class StatusPanel;
struct ExploreRequest;

class MainWindow : public QMainWindow {
  Q_OBJECT

 public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;

  // Opens a map in the Maps workspace and switches to it.
  void OpenMap(const QString& file);
  // Switches to the Mission workspace and starts the mission `request` describes.
  bool Explore(const ExploreRequest& request);

  [[nodiscard]] MapsWorkspace* Maps() const { return maps_; }
  [[nodiscard]] MissionWorkspace* Mission() const { return mission_; }
  [[nodiscard]] CalibrationWorkspace* Calibration() const { return calibration_; }
  [[nodiscard]] StatusPanel* Status() const { return status_panel_; }
  [[nodiscard]] const RecentFiles& Recent() const { return recent_; }
  // Names of the workspaces in the side bar, in order.
  [[nodiscard]] QStringList WorkspaceNames() const;
  [[nodiscard]] int CurrentWorkspace() const;
  void ShowWorkspace(int index);
  // Every menu action, for tests to find shortcuts and states by name.
  [[nodiscard]] QAction* FindAction(const QString& object_name) const;

 protected:
  void closeEvent(QCloseEvent* event) override;

 private:
  void AddWorkspace(QWidget* workspace, const QString& name, const QString& tip);
  void CreateActions();
  void CreateMenus();
  void CreateToolBar();
  void RestoreSettings();
  void SaveSettings() const;
  void RebuildRecentMenu();
  void UpdateActionStates();
  void SyncLayerActions();

  void OpenMapWithDialog();
  void ExportWithDialog(ExportKind kind);
  void SaveViewWithDialog();
  void ShowAbout();
  void ShowError(const QString& message);
  [[nodiscard]] QString LastDirectory() const;
  void RememberDirectory(const QString& file);

  QListWidget* sidebar_ = nullptr;
  QStackedWidget* stack_ = nullptr;
  MapsWorkspace* maps_ = nullptr;
  MissionWorkspace* mission_ = nullptr;
  CalibrationWorkspace* calibration_ = nullptr;
  StatusPanel* status_panel_ = nullptr;
  RecentFiles recent_;

  QAction* open_action_ = nullptr;
  QAction* save_view_action_ = nullptr;
  QAction* quit_action_ = nullptr;
  QAction* static_action_ = nullptr;
  QAction* dynamic_action_ = nullptr;
  QAction* colour_height_action_ = nullptr;
  QAction* colour_occupancy_action_ = nullptr;
  QAction* reset_camera_action_ = nullptr;
  QAction* cancel_action_ = nullptr;
  QAction* about_action_ = nullptr;
  std::vector<QAction*> export_actions_;
  std::vector<QAction*> workspace_actions_;
  QMenu* recent_menu_ = nullptr;
  QMenu* export_menu_ = nullptr;
};

}  // namespace dynamap::app::gui
