// The Mission workspace's logic against the real runtime on the small office at 160×120:
// start / pause / resume / stop transitions and the buttons they enable, the report at the
// end, a world file that cannot be opened, and the projected grid's picture.
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

#include "GuiTestSupport.hpp"
#include "dynamap/app/gui/GridView.hpp"
#include "dynamap/app/gui/MissionPanel.hpp"
#include "dynamap/app/gui/MissionSession.hpp"
#include "dynamap/app/gui/MissionWorkspace.hpp"
#include "dynamap/app/gui/ResourceFiles.hpp"

namespace dynamap::app::gui::test {

class MissionWorkspaceTest : public QObject {
  Q_OBJECT

 private slots:
  void StartPauseResumeStopEndsWithReport() {
    QTemporaryDir dir;
    MissionWorkspace workspace;
    ConfigureShortMission(workspace, dir.path(), 30.0);
    MissionPanel* panel = workspace.Panel();
    QVERIFY(panel->StartButton()->isEnabled());
    QVERIFY(!panel->StopButton()->isEnabled());

    QVERIFY(workspace.StartMission());
    QCOMPARE(workspace.Session()->Phase(), MissionPhase::kStarting);
    QVERIFY(!workspace.StartMission());  // One mission at a time.
    QTRY_VERIFY_WITH_TIMEOUT(workspace.Session()->Phase() != MissionPhase::kStarting, 20000);
    QVERIFY2(workspace.Session()->Phase() == MissionPhase::kRunning,
             qPrintable(workspace.Session()->LastError()));
    QVERIFY(!panel->StartButton()->isEnabled());
    QVERIFY(panel->PauseButton()->isEnabled());
    QVERIFY(!workspace.ResumeMission());  // Not paused.

    QVERIFY(workspace.PauseMission());
    QCOMPARE(workspace.Session()->Phase(), MissionPhase::kPaused);
    QVERIFY(panel->ResumeButton()->isEnabled());
    QVERIFY(!workspace.PauseMission());
    QVERIFY(workspace.ResumeMission());
    QCOMPARE(workspace.Session()->Phase(), MissionPhase::kRunning);

    QTRY_VERIFY_WITH_TIMEOUT(workspace.Session()->Snapshot().sim_time_s > 0.5, 20000);
    // The 3D view follows the live map, long before the first save (every 600 s here).
    QTRY_VERIFY_WITH_TIMEOUT(workspace.Session()->Map() != nullptr, 20000);
    QVERIFY(workspace.Session()->Map()->static_count > 0);
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("map.ot"))));
    QVERIFY(workspace.StopMission());
    QVERIFY(workspace.Session()->Phase() == MissionPhase::kFinishing ||
            workspace.Session()->Phase() == MissionPhase::kFinished);
    QVERIFY(!panel->StopButton()->isEnabled());
    QTRY_COMPARE_WITH_TIMEOUT(workspace.Session()->Phase(), MissionPhase::kFinished, 30000);
    QVERIFY(workspace.Session()->Report().has_value());
    QVERIFY(workspace.Session()->Report()->mission_time_s < 30.0);
    QVERIFY(QFileInfo::exists(dir.filePath(QStringLiteral("report.json"))));
    QVERIFY(panel->StartButton()->isEnabled());
    QVERIFY(workspace.Session()->Snapshot().grid != nullptr);
    QTRY_VERIFY_WITH_TIMEOUT(workspace.Session()->Map() != nullptr, 20000);
    QVERIFY(workspace.Session()->Map()->static_count > 0);
  }

  void WorldThatCannotBeOpenedFailsWithItsName() {
    QTemporaryDir dir;
    MissionWorkspace workspace;
    ConfigureShortMission(workspace, dir.path(), 2.0);
    workspace.Panel()->SetWorldFile(QStringLiteral("/nonexistent/world.yaml"));
    QSignalSpy errors(&workspace, &MissionWorkspace::ErrorOccurred);
    QVERIFY(workspace.StartMission());
    QTRY_COMPARE_WITH_TIMEOUT(workspace.Session()->Phase(), MissionPhase::kFailed, 10000);
    QCOMPARE(errors.count(), 1);
    QVERIFY2(errors.at(0).at(0).toString().contains(QStringLiteral("/nonexistent/world.yaml")),
             qPrintable(errors.at(0).at(0).toString()));
    QVERIFY(workspace.Panel()->StartButton()->isEnabled());  // The operator can try again.
  }

  void StopWhileStartingReturnsToIdle() {
    QTemporaryDir dir;
    MissionWorkspace workspace;
    ConfigureShortMission(workspace, dir.path(), 2.0);
    QVERIFY(workspace.StartMission());
    QVERIFY(workspace.StopMission());
    QCOMPARE(workspace.Session()->Phase(), MissionPhase::kIdle);
    QTest::qWait(300);
    QCOMPARE(workspace.Session()->Phase(), MissionPhase::kIdle);
  }

  void GridPictureIsNorthUpWithOneColourPerState() {
    auto grid = std::make_shared<planning::GridMap>(3, 2, 0.05);
    grid->Set({0, 0}, planning::CellState::kNavigable);
    grid->Set({2, 1}, planning::CellState::kObstacle);
    const QImage image = GridToImage(*grid);
    QCOMPARE(image.size(), QSize(3, 2));
    // Row y = 0 (south) is the image's bottom row.
    QVERIFY(qGray(image.pixel(0, 1)) > 200);  // navigable: light
    QVERIFY(qGray(image.pixel(2, 0)) < 80);   // obstacle: dark
    QVERIFY(image.pixel(1, 0) != image.pixel(0, 1));  // unknown differs from navigable
  }

 private:
  static void ConfigureShortMission(MissionWorkspace& workspace, const QString& out,
                                    double seconds) {
    MissionPanel* panel = workspace.Panel();
    panel->SetWorldFile(ResourcePath(QStringLiteral("worlds/small_office.yaml")));
    panel->SetKinectSize(160, 120);
    panel->SetTimeLimit(seconds);
    panel->SetSavePeriod(600.0);
    panel->SetOutputDir(out);
  }
};

std::unique_ptr<QObject> MakeMissionWorkspaceTest() {
  return std::make_unique<MissionWorkspaceTest>();
}

}  // namespace dynamap::app::gui::test

#include "MissionWorkspaceTest.moc"
