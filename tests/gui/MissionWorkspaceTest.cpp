// The Mission workspace's logic against the real runtime on the small office at 160×120:
// start / pause / resume / stop transitions and the buttons they enable, the report at the
// end, a world file that cannot be opened, a recording replayed (source choice, progress,
// live figures) or refused, and the projected grid's picture.
#include <QComboBox>
#include <QDir>
#include <QFile>
#include <QLineEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>

#include "GuiTestSupport.hpp"
#include "dynamap/app/gui/GridView.hpp"
#include "dynamap/app/gui/MissionPanel.hpp"
#include "dynamap/app/gui/MissionSession.hpp"
#include "dynamap/app/gui/MissionWorkspace.hpp"
#include "dynamap/app/gui/ResourceFiles.hpp"
#include "dynamap/app/runtime/MissionRuntime.hpp"

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

  void ChoosingARecordingBuildsAReplay() {
    MissionWorkspace workspace;
    MissionPanel* panel = workspace.Panel();
    panel->SetRecording(QStringLiteral("/data/runs/office-1"));
    runtime::MissionConfig config = panel->BuildConfig();
    QCOMPARE(QString::fromStdString(config.recording_dir), QStringLiteral("/data/runs/office-1"));
    QVERIFY(config.world_file.empty());
    QVERIFY(config.rig_file.empty());  // As recorded.
    auto* recording = panel->findChild<QLineEdit*>(QStringLiteral("mission_recording"));
    QVERIFY(recording != nullptr && recording->isVisibleTo(panel));

    panel->SetWorldFile(ResourcePath(QStringLiteral("worlds/small_office.yaml")));
    config = panel->BuildConfig();
    QVERIFY(config.recording_dir.empty());
    QVERIFY(QString::fromStdString(config.world_file).endsWith(QStringLiteral("small_office.yaml")));
    QVERIFY(QString::fromStdString(config.rig_file).endsWith(QStringLiteral("two_kinects.yaml")));
    QVERIFY(!recording->isVisibleTo(panel));
  }

  void TheTargetStrategyChosenGoesIntoTheMission() {
    MissionWorkspace workspace;
    MissionPanel* panel = workspace.Panel();
    QCOMPARE(panel->BuildConfig().planning.targets.strategy, std::string("tour"));
    auto* targets = panel->findChild<QComboBox*>(QStringLiteral("mission_targets"));
    QVERIFY(targets != nullptr && targets->isVisibleTo(panel));
    QCOMPARE(targets->count(), 3);
    targets->setCurrentIndex(targets->findData(QStringLiteral("gain")));
    QCOMPARE(panel->BuildConfig().planning.targets.strategy, std::string("gain"));
    panel->SetTargetStrategy(QStringLiteral("nearest-frontier"));
    QCOMPARE(targets->currentText(), QStringLiteral("Nearest frontier (baseline)"));
    QCOMPARE(panel->BuildConfig().planning.targets.strategy, std::string("nearest-frontier"));
    panel->SetTargetStrategy(QStringLiteral("no-such-strategy"));  // Ignored.
    QCOMPARE(panel->BuildConfig().planning.targets.strategy, std::string("nearest-frontier"));
  }

  // A short recorded mission replayed in the workspace: the progress bar runs through the
  // recording and the live figures include the ATE and explored share from its truth.
  void ReplayShowsProgressThroughTheRecordingAndLiveFigures() {
    QTemporaryDir dir;
    runtime::MissionConfig record;
    record.world_file = ResourcePath(QStringLiteral("worlds/small_office.yaml")).toStdString();
    record.out_dir = dir.filePath(QStringLiteral("recorded")).toStdString();
    record.kinect_width = 160;
    record.kinect_height = 120;
    record.poses = runtime::PoseSource::kGroundTruth;
    record.max_time_s = 5.0;
    record.record = true;
    {
      auto recorded = runtime::MissionRuntime::Create(record);
      QVERIFY2(recorded.ok(), recorded.ok() ? "" : recorded.error().message.c_str());
      (*recorded)->Start();
      (*recorded)->Wait();
      QVERIFY((*recorded)->Finish().ok());
    }
    MissionWorkspace workspace;
    MissionPanel* panel = workspace.Panel();
    panel->SetRecording(dir.filePath(QStringLiteral("recorded/recording")));
    panel->SetSavePeriod(600.0);
    panel->SetOutputDir(dir.filePath(QStringLiteral("replay")));
    auto* progress = panel->findChild<QProgressBar*>(QStringLiteral("mission_progress"));
    QVERIFY(progress != nullptr);
    QVERIFY(workspace.StartMission());
    QTRY_VERIFY_WITH_TIMEOUT(workspace.Session()->Phase() == MissionPhase::kRunning ||
                                 workspace.Session()->Phase() == MissionPhase::kFinishing ||
                                 workspace.Session()->Phase() == MissionPhase::kFinished ||
                                 workspace.Session()->Phase() == MissionPhase::kFailed,
                             20000);
    QVERIFY2(workspace.Session()->Phase() != MissionPhase::kFailed,
             qPrintable(workspace.Session()->LastError()));
    QTRY_COMPARE_WITH_TIMEOUT(workspace.Session()->Phase(), MissionPhase::kFinished, 60000);
    const runtime::MissionSnapshot& last = workspace.Session()->Snapshot();
    QVERIFY(std::abs(last.time_limit_s - 5.0) < 0.05);
    QCOMPARE(progress->value(), 1000);
    QVERIFY(last.ate_so_far_m.has_value());
    QVERIFY(last.explored_free_fraction.has_value());
    QVERIFY2(panel->FiguresText().contains(QStringLiteral("% of the reachable floor")),
             qPrintable(panel->FiguresText()));
    QVERIFY(workspace.Session()->Report()->frames_processed > 200);
  }

  void RecordingItCannotReplayFailsWithTheReason() {
    QTemporaryDir dir;
    QDir(dir.path()).mkpath(QStringLiteral("tum/depth"));
    QFile::copy(QString::fromUtf8(DYNAMAP_SHARED_DATA_DIR) + QStringLiteral("/tum/TUM_depth.png"),
                dir.filePath(QStringLiteral("tum/depth/1.000000.png")));
    QFile index(dir.filePath(QStringLiteral("tum/depth.txt")));
    QVERIFY(index.open(QIODevice::WriteOnly));
    index.write("1.000000 depth/1.000000.png\n");
    index.close();
    MissionWorkspace workspace;
    workspace.Panel()->SetRecording(dir.filePath(QStringLiteral("tum")));
    workspace.Panel()->SetOutputDir(dir.filePath(QStringLiteral("out")));
    QSignalSpy errors(&workspace, &MissionWorkspace::ErrorOccurred);
    QVERIFY(workspace.StartMission());
    QTRY_COMPARE_WITH_TIMEOUT(workspace.Session()->Phase(), MissionPhase::kFailed, 10000);
    QCOMPARE(errors.count(), 1);
    QVERIFY2(errors.at(0).at(0).toString().contains(QStringLiteral("no odometry.txt")),
             qPrintable(errors.at(0).at(0).toString()));
  }

  // The real robot as the source: its devices are opened before anything runs, and a
  // missing one fails the start with its name (the runtime on emulated devices is
  // HardwareMissionTest's).
  void RobotThatIsNotConnectedFailsNamingTheDevice() {
    QTemporaryDir dir;
    MissionWorkspace workspace;
    RobotSetup robot;
    robot.rmp_port = "/dev/ttyUSB-dynamap-missing";
    robot.pad = "/dev/input/js-dynamap-missing";
    workspace.Panel()->SetRobot(robot);
    workspace.Panel()->SetOutputDir(dir.filePath(QStringLiteral("run")));
    const runtime::MissionConfig config = workspace.Panel()->BuildConfig();
    QVERIFY(config.world_file.empty() && config.recording_dir.empty());
    const auto setup = workspace.Panel()->BuildRobotSetup();
    QVERIFY(setup.has_value());
    QCOMPARE(QString::fromStdString(setup->rmp_port), QStringLiteral("/dev/ttyUSB-dynamap-missing"));
    QVERIFY(setup->imu_port.empty());  // No gyro.
    QSignalSpy errors(&workspace, &MissionWorkspace::ErrorOccurred);
    QVERIFY(workspace.StartMission());
    QTRY_COMPARE_WITH_TIMEOUT(workspace.Session()->Phase(), MissionPhase::kFailed, 10000);
    QCOMPARE(errors.count(), 1);
    const QString message = errors.at(0).at(0).toString();
    QVERIFY2(message.contains(QStringLiteral("Segway RMP")) &&
                 message.contains(QStringLiteral("/dev/ttyUSB-dynamap-missing")),
             qPrintable(message));
    QVERIFY(!QFileInfo::exists(dir.filePath(QStringLiteral("run/map.ot"))));
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

  void FrontierRegionsPassedOverAreCrossedWhereTheyLie() {
    auto grid = std::make_shared<planning::GridMap>(40, 40, 0.05);  // 2 x 2 m from (0, 0).
    for (int y = 0; y < 40; ++y) {
      for (int x = 0; x < 40; ++x) grid->Set({x, y}, planning::CellState::kNavigable);
    }
    GridView view;
    view.resize(200, 200);  // 100 px per metre, no margin.
    GridScene scene;
    scene.grid = grid;
    scene.pose = {0.2, 0.2, 0.0};
    scene.unreachable_frontiers = {{1.5, 1.5}};  // North-east: pixel (150, 50).
    scene.blacklisted_frontiers = {{0.5, 1.5}};  // North-west: pixel (50, 50).
    view.SetScene(scene);
    const QImage image = view.grab().toImage();
    const auto count = [&image](int cx, int cy, bool red) {
      int n = 0;
      for (int y = cy - 8; y <= cy + 8; ++y) {
        for (int x = cx - 8; x <= cx + 8; ++x) {
          const QRgb p = image.pixel(x, y);
          n += red ? (qRed(p) > 180 && qGreen(p) < 90 && qBlue(p) < 90)
                   : (qBlue(p) > 110 && qRed(p) < 70 && qGreen(p) < 100);
        }
      }
      return n;
    };
    QVERIFY(count(150, 50, true) > 15);
    QVERIFY(count(50, 50, false) > 15);
    QCOMPARE(count(150, 150, true), 0);  // Nothing south-east: north is up.
    QCOMPARE(count(50, 50, true), 0);
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
