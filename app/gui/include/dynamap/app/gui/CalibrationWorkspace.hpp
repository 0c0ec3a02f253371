// The Calibration workspace: the guided rig calibration against the simulator or a
// recording of the guided sequence made on the robot. It says
// what to do now, shows each step's progress (floor fits and their inlier share, degrees
// turned, metres driven straight and in arcs, ICP pairs per Kinect), both live depth
// images with the fitted floor tinted, lets the operator drive (or drive the step for
// them), then solves and shows the estimated rig with uncertainties and the residual
// plots, and saves the rig file.
#pragma once

#include <QString>
#include <QTimer>
#include <QWidget>
#include <memory>
#include <vector>

#include "dynamap/app/gui/BackgroundTask.hpp"
#include "dynamap/app/gui/CalibrationRun.hpp"

class QCheckBox;
class QComboBox;
class QFormLayout;
class QLineEdit;
class QLabel;
class QListWidget;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace dynamap::app::gui {

class CalibrationResults;
class DepthPreview;

class CalibrationWorkspace : public QWidget {
  Q_OBJECT

 public:
  explicit CalibrationWorkspace(QWidget* parent = nullptr);
  ~CalibrationWorkspace() override;

  // The session the setup controls describe (results next to a rig file in `out_dir`).
  [[nodiscard]] CalibrationSetup BuildSetup() const;
  // Starts a session in the background; ends in SessionStarted or ErrorOccurred.
  void BeginSession(const CalibrationSetup& setup);
  void EndSession();
  // Selects the simulator in `file`'s room as the source.
  void SetWorldFile(const QString& file);
  // Selects the recording in folder `dir` as the source.
  void SetRecording(const QString& dir);
  void SetOutputDir(const QString& dir);
  void SetImageWidth(int width);
  void SetSpeed(double sim_seconds_per_wall_second);

  // Wizard actions (the buttons); ignored without a session.
  void DriveStep();
  void Next();
  void SkipStep();
  void Solve();
  void SaveTo(const QString& file);

  [[nodiscard]] bool HasSession() const { return run_ != nullptr; }
  // The setup names a recording to replay rather than the simulator.
  [[nodiscard]] bool ReplaysRecording() const;
  [[nodiscard]] bool Starting() const { return start_task_->Running(); }
  [[nodiscard]] const CalibrationState& LastState() const { return state_; }
  [[nodiscard]] const QString& LastMessage() const { return last_message_; }
  [[nodiscard]] CalibrationResults* Results() const { return results_; }
  // Reads the run's state now instead of waiting for the timer (tests).
  void Refresh();

 signals:
  void SessionStarted();
  void ErrorOccurred(const QString& message);
  void StatusMessage(const QString& message);

 private:
  QWidget* MakeSetupGroup();
  QWidget* MakeWizardGroup();
  QWidget* MakeDriveGroup();
  void ShowState();
  [[nodiscard]] std::vector<QWidget*> SetupFields() const;
  void ShowSource();  // The setup rows that belong to the chosen source.
  void SaveWithDialog();

  std::shared_ptr<CalibrationRun> run_;
  CalibrationState state_;
  std::uint64_t seen_message_ = 0;
  const calibration::SolverResult* shown_result_ = nullptr;
  std::size_t shown_plots_ = 0;
  QString last_message_;
  QTimer poll_timer_;
  BackgroundTask* start_task_ = nullptr;

  QWidget* setup_ = nullptr;
  QFormLayout* setup_form_ = nullptr;
  QComboBox* source_ = nullptr;
  QWidget* recording_row_ = nullptr;
  QLineEdit* recording_ = nullptr;
  QComboBox* world_ = nullptr;
  QComboBox* rig_ = nullptr;
  QSpinBox* seed_ = nullptr;
  QComboBox* width_ = nullptr;
  QComboBox* pace_ = nullptr;
  QString out_dir_;
  QPushButton* begin_ = nullptr;
  QListWidget* steps_ = nullptr;
  QLabel* instruction_ = nullptr;
  QLabel* detail_ = nullptr;
  QProgressBar* step_progress_ = nullptr;
  QLabel* counters_ = nullptr;
  QWidget* drive_ = nullptr;
  QPushButton* auto_drive_ = nullptr;
  QPushButton* next_ = nullptr;
  QPushButton* skip_ = nullptr;
  QPushButton* solve_ = nullptr;
  QComboBox* redo_ = nullptr;
  QPushButton* save_ = nullptr;
  QCheckBox* allow_uncalibrated_ = nullptr;
  DepthPreview* depth0_ = nullptr;
  DepthPreview* depth1_ = nullptr;
  CalibrationResults* results_ = nullptr;
};

}  // namespace dynamap::app::gui
