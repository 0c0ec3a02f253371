// The Maps workspace: open a saved dual map (.ot) or any OctoMap (.bt), look at the static
// and dynamic layers in 3D, slice by height, colour, pick voxels and export. Loading and
// exporting run on a BackgroundTask; the view only ever sees finished, immutable data.
#pragma once

#include <QString>
#include <QWidget>
#include <memory>
#include <optional>

#include "dynamap/app/gui/BackgroundTask.hpp"
#include "dynamap/app/gui/MapExportFormats.hpp"
#include "dynamap/app/gui/VoxelSet.hpp"
#include "dynamap/mapping/DualOcTree.hpp"

class QLabel;
class QProgressBar;
class QPushButton;

namespace dynamap::app::gui {

class MapControls;
class VoxelView;

// A map as loaded: never changed after the worker hands it over, so exports on other
// threads may read it while the view draws it.
struct LoadedMap {
  QString file;
  std::unique_ptr<mapping::DualOcTree> tree;
  std::shared_ptr<const VoxelSet> voxels;
  bool dual = false;  // saved by dynamap with both channels (else a plain OctoMap).
};

class MapsWorkspace : public QWidget {
  Q_OBJECT

 public:
  explicit MapsWorkspace(QWidget* parent = nullptr);
  ~MapsWorkspace() override;

  // Starts loading `file` in the background; ends in MapOpened or ErrorOccurred (or
  // nothing, when cancelled).
  void OpenFile(const QString& file);
  // Starts writing the open map as `kind`; ends in ExportFinished or ErrorOccurred.
  void Export(ExportKind kind, const QString& file);
  // Writes what the 3D view shows now; false (and ErrorOccurred) when it cannot.
  bool SaveViewImage(const QString& file);
  void CancelWork();

  [[nodiscard]] bool Busy() const;
  [[nodiscard]] std::shared_ptr<const LoadedMap> Map() const { return map_; }
  [[nodiscard]] const QString& LastError() const { return last_error_; }
  [[nodiscard]] MapControls* Controls() const { return controls_; }
  [[nodiscard]] VoxelView* View() const { return view_; }

 signals:
  void MapOpened(const QString& file);
  void ExportFinished(const QString& file);
  // A full sentence naming the file and the cause, for a message box and the status bar.
  void ErrorOccurred(const QString& message);
  void BusyChanged(bool busy);
  void StatusMessage(const QString& message);

 private:
  void ShowMap(std::shared_ptr<const LoadedMap> map);
  void Fail(const QString& message);
  void OnFilterChanged();
  void OnColourModeChanged();
  void OnTaskProgress(int percent, const QString& stage);
  void OnTaskFinished(bool cancelled, const QString& error);

  MapControls* controls_ = nullptr;
  VoxelView* view_ = nullptr;
  QWidget* progress_strip_ = nullptr;
  QLabel* progress_label_ = nullptr;
  QProgressBar* progress_bar_ = nullptr;
  QPushButton* cancel_button_ = nullptr;
  BackgroundTask* task_ = nullptr;
  std::shared_ptr<const LoadedMap> map_;
  QString last_error_;
};

}  // namespace dynamap::app::gui
