// The permanent part of the status bar: how the robot is connected, the mission state and
// the frames the mapper dropped. Fed with plain values (runtime snapshots), never polled.
#pragma once

#include <QString>
#include <QWidget>
#include <cstdint>
#include <optional>

class QLabel;

namespace dynamap::app::gui {

enum class RobotConnection { kNone, kSimulator, kRecording, kHardware };

[[nodiscard]] QString ConnectionText(RobotConnection connection);

class StatusPanel : public QWidget {
  Q_OBJECT

 public:
  explicit StatusPanel(QWidget* parent = nullptr);

  void SetConnection(RobotConnection connection);
  void SetMissionState(const QString& state);
  // nullopt while no mission runs: there is nothing to count.
  void SetDroppedFrames(std::optional<std::uint64_t> dropped);

  [[nodiscard]] QString ConnectionLabel() const;
  [[nodiscard]] QString MissionLabel() const;
  [[nodiscard]] QString DroppedLabel() const;

 private:
  QLabel* connection_ = nullptr;
  QLabel* mission_ = nullptr;
  QLabel* dropped_ = nullptr;
};

}  // namespace dynamap::app::gui
