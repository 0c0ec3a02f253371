// The Calibration workspace's wizard against the simulator at 160 px: Next is refused until
// the floor step is complete, standing still completes it, Next and Skip move through the
// steps, solving shows the rig table, a recording of the guided sequence is replayed and
// solved, and a room file that cannot be opened is an error naming it.
#include <QPushButton>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>

#include "GuiTestSupport.hpp"
#include "dynamap/app/gui/CalibrationResults.hpp"
#include "dynamap/app/gui/CalibrationWorkspace.hpp"
#include "dynamap/app/gui/ResourceFiles.hpp"
#include "dynamap/app/gui/RigView.hpp"

namespace dynamap::app::gui::test {

namespace cal = calibration;

class CalibrationWorkspaceTest : public QObject {
  Q_OBJECT

 private slots:
  void FloorStepCompletesStandingStillThenStepsAdvance() {
    QTemporaryDir dir;
    CalibrationWorkspace workspace;
    Begin(workspace, dir.path());
    QCOMPARE(workspace.LastState().progress.step, cal::SessionStep::kFloor);

    if (!workspace.LastState().progress.complete) {
      workspace.Next();  // Refused: the floor step has too few fits yet.
      QTRY_VERIFY_WITH_TIMEOUT(!workspace.LastMessage().isEmpty() ||
                                   workspace.LastState().progress.complete, 5000);
    }
    QTRY_VERIFY_WITH_TIMEOUT(workspace.LastState().progress.complete, 30000);
    QVERIFY(!workspace.LastState().depth.empty());
    workspace.Next();
    QTRY_COMPARE_WITH_TIMEOUT(workspace.LastState().progress.step, cal::SessionStep::kTurn, 5000);
    workspace.SkipStep();
    QTRY_COMPARE_WITH_TIMEOUT(workspace.LastState().progress.step, cal::SessionStep::kStraight,
                              5000);
  }

  void SolvingShowsTheRigWithUncertainties() {
    QTemporaryDir dir;
    CalibrationWorkspace workspace;
    Begin(workspace, dir.path());
    QTRY_VERIFY_WITH_TIMEOUT(workspace.LastState().progress.complete, 30000);
    workspace.Next();
    QTRY_COMPARE_WITH_TIMEOUT(workspace.LastState().progress.step, cal::SessionStep::kTurn, 5000);
    workspace.Solve();
    QTRY_COMPARE_WITH_TIMEOUT(workspace.LastState().progress.step, cal::SessionStep::kReview,
                              60000);
    QTRY_VERIFY_WITH_TIMEOUT(workspace.Results()->Table()->rowCount() > 0, 5000);
    // 7 parameters per Kinect and the two wheel scales.
    QCOMPARE(workspace.Results()->Table()->rowCount(), 2 * 7 + 2);
    // Without turning, x/y cannot be calibrated: saving is refused unless allowed.
    workspace.SaveTo(dir.filePath(QStringLiteral("rig.yaml")));
    QTRY_VERIFY_WITH_TIMEOUT(!workspace.LastMessage().isEmpty(), 5000);
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("rig.yaml"))));
  }

  // A recording of the guided sequence (the calibration room's teleop script, first 40 s:
  // floor and turns) replayed: no driving, the recording's progress, then the solve.
  void RecordingIsReplayedThenSolved() {
    QTemporaryDir dir;
    const QString recording = dir.filePath(QStringLiteral("recording"));
    QVERIFY(RecordCalibrationRoom(recording, 40));

    CalibrationWorkspace workspace;
    workspace.SetRecording(recording);
    workspace.SetSpeed(0.0);
    workspace.SetOutputDir(dir.path());
    QCOMPARE(QString::fromStdString(workspace.BuildSetup().recording_dir), recording);
    QSignalSpy started(&workspace, &CalibrationWorkspace::SessionStarted);
    workspace.BeginSession(workspace.BuildSetup());
    QVERIFY(started.wait(20000));
    // Generous: the wait ends as soon as the replay does, which took 94 s once while two
    // explorations shared the machine's two cores.
    QTRY_VERIFY_WITH_TIMEOUT(workspace.LastState().replay_fraction >= 1.0, 240000);
    QVERIFY(workspace.LastState().replay);
    // The floor step ended when the wheels first moved; the turns were counted.
    QVERIFY(workspace.LastState().progress.step != cal::SessionStep::kFloor);
    QVERIFY(workspace.LastState().progress.turned_left_deg > 270.0);
    QVERIFY(!workspace.LastState().depth.empty());
    auto* drive = workspace.findChild<QPushButton*>(QStringLiteral("calibration_drive_step"));
    QVERIFY(drive != nullptr);
    QVERIFY(!drive->isEnabled());  // A recording is not driven.

    workspace.Solve();
    QTRY_COMPARE_WITH_TIMEOUT(workspace.LastState().progress.step, cal::SessionStep::kReview,
                              60000);
    QTRY_COMPARE_WITH_TIMEOUT(workspace.Results()->Table()->rowCount(), 2 * 7 + 2, 5000);
    // The rig is drawn on the robot where it was estimated, with its uncertainty.
    const RigView* rig = workspace.Results()->Rig3d();
    QCOMPARE(rig->DrawnPoses().size(), std::size_t{2});
    const auto& estimate = workspace.LastState().result->kinects[0].parameters;
    QVERIFY((rig->DrawnPoses()[0].translation() -
             Eigen::Vector3d(estimate[3].estimate, estimate[4].estimate, estimate[5].estimate))
                .norm() < 1e-9);
    QVERIFY(std::abs(rig->DrawnSemiAxes()[0].x() - 3.0 * estimate[3].std_dev) < 1e-12);
  }

  void RoomThatCannotBeOpenedIsAnErrorNamingIt() {
    QTemporaryDir dir;
    CalibrationWorkspace workspace;
    workspace.SetWorldFile(QStringLiteral("/nonexistent/room.yaml"));
    workspace.SetOutputDir(dir.path());
    QSignalSpy errors(&workspace, &CalibrationWorkspace::ErrorOccurred);
    workspace.BeginSession(workspace.BuildSetup());
    QVERIFY(errors.wait(10000));
    QVERIFY(errors.at(0).at(0).toString().contains(QStringLiteral("/nonexistent/room.yaml")));
    QVERIFY(!workspace.HasSession());
  }

 private:
  static void Begin(CalibrationWorkspace& workspace, const QString& out) {
    workspace.SetWorldFile(ResourcePath(QStringLiteral("worlds/calibration_room.yaml")));
    workspace.SetImageWidth(160);
    workspace.SetSpeed(0.0);
    workspace.SetOutputDir(out);
    QSignalSpy started(&workspace, &CalibrationWorkspace::SessionStarted);
    workspace.BeginSession(workspace.BuildSetup());
    QVERIFY(started.wait(20000));
    QVERIFY(workspace.HasSession());
  }
};

std::unique_ptr<QObject> MakeCalibrationWorkspaceTest() {
  return std::make_unique<CalibrationWorkspaceTest>();
}

}  // namespace dynamap::app::gui::test

#include "CalibrationWorkspaceTest.moc"
