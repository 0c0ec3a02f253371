#include "dynamap/app/gui/StatusPanel.hpp"

#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>

namespace dynamap::app::gui {

namespace {

QFrame* Separator() {
  auto* line = new QFrame;
  line->setFrameShape(QFrame::VLine);
  line->setFrameShadow(QFrame::Sunken);
  return line;
}

}  // namespace

QString ConnectionText(RobotConnection connection) {
  switch (connection) {
    case RobotConnection::kNone:
      return QObject::tr("not connected");
    case RobotConnection::kSimulator:
      return QObject::tr("simulator");
    case RobotConnection::kRecording:
      return QObject::tr("recording");
    case RobotConnection::kHardware:
      return QObject::tr("hardware");
  }
  return QString();
}

StatusPanel::StatusPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  connection_ = new QLabel;
  mission_ = new QLabel;
  dropped_ = new QLabel;
  connection_->setToolTip(tr("Where sensor data comes from"));
  dropped_->setToolTip(tr("Depth frames the mapper could not keep up with (run mode)"));
  layout->addWidget(connection_);
  layout->addWidget(Separator());
  layout->addWidget(mission_);
  layout->addWidget(Separator());
  layout->addWidget(dropped_);
  SetConnection(RobotConnection::kNone);
  SetMissionState(tr("none"));
  SetDroppedFrames(std::nullopt);
}

void StatusPanel::SetConnection(RobotConnection connection) {
  connection_->setText(tr("Robot: %1").arg(ConnectionText(connection)));
}

void StatusPanel::SetMissionState(const QString& state) {
  mission_->setText(tr("Mission: %1").arg(state));
}

void StatusPanel::SetDroppedFrames(std::optional<std::uint64_t> dropped) {
  dropped_->setText(dropped ? tr("Dropped frames: %1").arg(*dropped)
                            : tr("Dropped frames: –"));
}

QString StatusPanel::ConnectionLabel() const { return connection_->text(); }
QString StatusPanel::MissionLabel() const { return mission_->text(); }
QString StatusPanel::DroppedLabel() const { return dropped_->text(); }

}  // namespace dynamap::app::gui
