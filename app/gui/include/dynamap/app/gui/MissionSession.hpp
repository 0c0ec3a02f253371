// One mission as the Mission workspace drives it: creates a runtime::MissionRuntime off the
// GUI thread, starts, pauses, resumes and stops it, pulls Snapshot() at a few Hz, turns the
// runtime's map copies into voxels for the 3D view (about once a second), and calls
// Finish() off the GUI thread when the mission ends. The GUI thread never waits for the
// runtime.
#pragma once

#include <QDateTime>
#include <QElapsedTimer>
#include <QObject>
#include <QString>
#include <QTimer>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dynamap/app/gui/BackgroundTask.hpp"
#include "dynamap/app/gui/VoxelSet.hpp"
#include "dynamap/app/runtime/MissionConfig.hpp"
#include "dynamap/app/runtime/MissionSnapshot.hpp"

namespace dynamap::app::runtime {
class MissionRuntime;
struct PadState;
}

namespace dynamap::app::gui {

enum class MissionPhase {
  kIdle,       // Nothing run yet.
  kStarting,   // Loading world, rig and robot.
  kRunning,
  kPaused,
  kFinishing,  // Ended (goal, time limit or Stop); scoring and writing results.
  kFinished,   // Report available.
  kFailed,     // Could not be created or finished; LastError() says why.
};

[[nodiscard]] QString PhaseName(MissionPhase phase);

// The real robot's devices for a mission on it (the "Real robot" source).
struct RobotSetup {
  std::string rmp_port;              // Segway RMP serial device.
  std::string imu_port;              // Xsens gyro serial device; empty: no gyro.
  std::string pad;                   // Joystick device of the gamepad (dead-man button).
  std::vector<std::string> cameras;  // One per rig Kinect: URI, serial:XYZ or index; empty
                                     // for a one-Kinect rig: the only camera connected.
};

class MissionSession : public QObject {
  Q_OBJECT

 public:
  explicit MissionSession(QObject* parent = nullptr);
  // Stops a running mission and waits for its threads (they leave within one cycle).
  ~MissionSession() override;

  // From idle, finished or failed. Returns false (and changes nothing) otherwise. With
  // `robot`, the devices are opened (off the GUI thread) and the mission runs on them.
  bool Start(runtime::MissionConfig config, std::optional<RobotSetup> robot = std::nullopt);
  bool Pause();
  bool Resume();
  // Ends a starting, running or paused mission; results are still scored and written.
  bool Stop();

  [[nodiscard]] MissionPhase Phase() const { return phase_; }
  [[nodiscard]] const runtime::MissionSnapshot& Snapshot() const { return snapshot_; }
  [[nodiscard]] const std::optional<runtime::MissionReport>& Report() const { return report_; }
  [[nodiscard]] const runtime::MissionConfig& Config() const { return config_; }
  [[nodiscard]] std::shared_ptr<const VoxelSet> Map() const { return map_; }
  [[nodiscard]] const QString& LastError() const { return last_error_; }
  // On the real robot: whether the pad's dead-man button is held now.
  [[nodiscard]] std::optional<bool> DeadmanHeld() const;
  // Snapshot period, ms (default 250: 4 Hz).
  void SetPollInterval(int ms) { poll_timer_.setInterval(ms); }

 signals:
  void PhaseChanged(dynamap::app::gui::MissionPhase phase);
  void SnapshotUpdated();
  void MapUpdated();
  void Finished();
  void ErrorOccurred(const QString& message);

 private:
  void SetPhase(MissionPhase phase);
  void Fail(const QString& message);
  void Poll();
  // While running: the runtime's newest map copy into voxels (off the GUI thread), and
  // the next copy asked for at most once a second. After the end: the final map.ot.
  void UpdateLiveMap();
  void ReloadMapIfNewer();
  void BeginFinish();

  runtime::MissionConfig config_;
  std::shared_ptr<runtime::MissionRuntime> runtime_;  // On the robot it holds the devices.
  std::shared_ptr<runtime::PadState> pad_state_;     // On the robot.
  MissionPhase phase_ = MissionPhase::kIdle;
  runtime::MissionSnapshot snapshot_;
  std::optional<runtime::MissionReport> report_;
  std::shared_ptr<const VoxelSet> map_;
  QDateTime map_loaded_time_;
  std::uint64_t map_copy_version_ = 0;  // Of the runtime's map copy last drawn.
  QElapsedTimer map_copy_requested_;
  QString last_error_;
  QTimer poll_timer_;
  BackgroundTask* lifecycle_task_ = nullptr;  // Create, then Finish.
  BackgroundTask* map_task_ = nullptr;        // Map copy or map.ot into voxels.
};

}  // namespace dynamap::app::gui
