// The left panel of the Mission workspace: what to run (a simulated world, a recording
// to replay or the real robot's devices, rig, pose source, Kinect resolution, time limit, pace, map save period,
// results folder), Start / Pause / Resume / Stop, the live figures of the running mission
// (with a progress bar through the time limit or the recording) and the report when it
// has ended.
#pragma once

#include <QString>
#include <QWidget>
#include <optional>

#include "dynamap/app/gui/MissionSession.hpp"
#include "dynamap/app/runtime/MissionConfig.hpp"
#include "dynamap/app/runtime/MissionSnapshot.hpp"

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QProgressBar;
class QLabel;
class QLineEdit;
class QPushButton;

namespace dynamap::app::gui {

class MissionPanel : public QWidget {
  Q_OBJECT

 public:
  explicit MissionPanel(QWidget* parent = nullptr);

  // The mission the controls describe; an empty results folder becomes a new folder under
  // ~/dynamap-missions named after the start time.
  [[nodiscard]] runtime::MissionConfig BuildConfig() const;
  // Selects `file` (adding it to the list when it is not one of resources/) and the
  // simulated world as the source.
  void SetWorldFile(const QString& file);
  // Selects the recording folder `dir` as the source.
  void SetRecording(const QString& dir);
  // Selects the real robot with these devices as the source.
  void SetRobot(const RobotSetup& setup);
  // The devices when the source is the real robot; nullopt otherwise.
  [[nodiscard]] std::optional<RobotSetup> BuildRobotSetup() const;
  void SetRigFile(const QString& file);
  void SetPoseSource(runtime::PoseSource source);
  // "gain", "tour" or "nearest-frontier" (planning::TargetPlannerConfig::strategy).
  void SetTargetStrategy(const QString& strategy);
  void SetKinectSize(int width, int height);
  void SetTimeLimit(double seconds);
  void SetSavePeriod(double seconds);
  void SetOutputDir(const QString& dir);

  // Enables the buttons and setup for `phase`.
  void ShowPhase(MissionPhase phase);
  void ShowSnapshot(const runtime::MissionSnapshot& snapshot);
  void ShowReport(const std::optional<runtime::MissionReport>& report, const QString& out_dir);
  // On the real robot: the pad's dead-man button (nullopt hides the row).
  void ShowDeadman(std::optional<bool> held);

  [[nodiscard]] QPushButton* StartButton() const { return start_; }
  [[nodiscard]] QPushButton* PauseButton() const { return pause_; }
  [[nodiscard]] QPushButton* ResumeButton() const { return resume_; }
  [[nodiscard]] QPushButton* StopButton() const { return stop_; }
  [[nodiscard]] QString FiguresText() const;

 signals:
  void StartRequested();
  void PauseRequested();
  void ResumeRequested();
  void StopRequested();

 private:
  QWidget* MakeSetupGroup();
  QWidget* MakeFiguresGroup();
  void BrowseFile(QComboBox* combo, const QString& title);
  [[nodiscard]] bool ReplaysRecording() const;
  [[nodiscard]] bool RunsOnRobot() const;
  void ShowSource();  // The rows that belong to the chosen source.

  QWidget* setup_ = nullptr;
  QFormLayout* setup_form_ = nullptr;
  QComboBox* source_ = nullptr;
  QWidget* world_row_ = nullptr;
  QWidget* recording_row_ = nullptr;
  QLineEdit* recording_ = nullptr;
  QWidget* robot_box_ = nullptr;
  QLineEdit* rmp_port_ = nullptr;
  QLineEdit* imu_port_ = nullptr;
  QLineEdit* pad_ = nullptr;
  QLineEdit* cameras_ = nullptr;
  QComboBox* world_ = nullptr;
  QComboBox* rig_ = nullptr;
  QComboBox* poses_ = nullptr;
  QComboBox* targets_ = nullptr;
  QComboBox* kinect_size_ = nullptr;
  QDoubleSpinBox* time_limit_ = nullptr;
  QComboBox* pace_ = nullptr;
  QDoubleSpinBox* save_period_ = nullptr;
  QLineEdit* out_dir_ = nullptr;
  QPushButton* start_ = nullptr;
  QPushButton* pause_ = nullptr;
  QPushButton* resume_ = nullptr;
  QPushButton* stop_ = nullptr;
  QLabel* state_ = nullptr;
  QLabel* sim_time_ = nullptr;
  QLabel* distance_ = nullptr;
  QLabel* frames_ = nullptr;
  QLabel* dropped_ = nullptr;
  QLabel* collisions_ = nullptr;
  QLabel* target_ = nullptr;
  QLabel* command_ = nullptr;
  QLabel* explored_ = nullptr;
  QLabel* deadman_ = nullptr;
  QFormLayout* figures_form_ = nullptr;
  QLabel* ate_ = nullptr;
  QProgressBar* progress_ = nullptr;
  QLabel* report_ = nullptr;
};

}  // namespace dynamap::app::gui
