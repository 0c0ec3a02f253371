// The main window: which workspaces it offers, shortcuts, menu toggles reaching the Maps
// workspace, the status bar, recent files and layout kept in QSettings, and what
// `dynamap gui --explore` starts with (or refuses to start with).
#include <QAction>
#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <memory>
#include <vector>

#include "GuiTestSupport.hpp"
#include "dynamap/app/gui/GuiLauncher.hpp"
#include "dynamap/app/gui/MainWindow.hpp"
#include "dynamap/app/gui/MapControls.hpp"
#include "dynamap/app/gui/MapsWorkspace.hpp"
#include "dynamap/app/gui/MissionPanel.hpp"
#include "dynamap/app/gui/MissionSession.hpp"
#include "dynamap/app/gui/MissionWorkspace.hpp"
#include "dynamap/app/gui/RecentFiles.hpp"
#include "dynamap/app/gui/ResourceFiles.hpp"
#include "dynamap/app/gui/StatusPanel.hpp"

namespace dynamap::app::gui::test {

class MainWindowTest : public QObject {
  Q_OBJECT

 private slots:
  void init() { QSettings().clear(); }

  void OffersOnlyWorkingWorkspaces() {
    MainWindow window;
    QCOMPARE(window.WorkspaceNames(),
             (QStringList{QStringLiteral("Calibration"), QStringLiteral("Mission"),
                          QStringLiteral("Maps")}));
    QCOMPARE(window.CurrentWorkspace(), 0);
  }

  void ActionsHaveShortcuts() {
    MainWindow window;
    QCOMPARE(window.FindAction(QStringLiteral("open_map"))->shortcut(),
             QKeySequence(QKeySequence::Open));
    QCOMPARE(window.FindAction(QStringLiteral("quit"))->shortcut(),
             QKeySequence(QKeySequence::Quit));
    QCOMPARE(window.FindAction(QStringLiteral("show_static"))->shortcut(),
             QKeySequence(Qt::Key_F5));
    QCOMPARE(window.FindAction(QStringLiteral("workspace_0"))->shortcut(),
             QKeySequence(Qt::CTRL | Qt::Key_1));
  }

  void ExportsDisabledUntilAMapIsOpen() {
    MainWindow window;
    QVERIFY(!window.FindAction(QStringLiteral("export_0"))->isEnabled());
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    window.OpenMap(Geb079Path());
    QTRY_VERIFY_WITH_TIMEOUT(window.Maps()->Map() != nullptr, 60000);
    QTRY_VERIFY(window.FindAction(QStringLiteral("export_0"))->isEnabled());
  }

  void StaticToggleActionReachesWorkspace() {
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    QAction* show_static = window.FindAction(QStringLiteral("show_static"));
    QVERIFY(show_static->isChecked());
    show_static->trigger();
    QVERIFY(!window.Maps()->Controls()->Filter().show_static);
    window.Maps()->Controls()->SetShowStatic(true);
    QVERIFY(show_static->isChecked());
  }

  void StatusBarShowsNoRobotWithoutMission() {
    MainWindow window;
    QVERIFY(window.Status()->ConnectionLabel().contains(QStringLiteral("not connected")));
    window.Status()->SetConnection(RobotConnection::kSimulator);
    window.Status()->SetDroppedFrames(12);
    QVERIFY(window.Status()->ConnectionLabel().contains(QStringLiteral("simulator")));
    QVERIFY(window.Status()->DroppedLabel().contains(QStringLiteral("12")));
  }

  void OpenedMapBecomesRecentAndPersists() {
    {
      MainWindow window;
      window.show();
      QVERIFY(QTest::qWaitForWindowExposed(&window));
      window.OpenMap(Geb079Path());
      QTRY_VERIFY_WITH_TIMEOUT(window.Maps()->Map() != nullptr, 60000);
      QCOMPARE(window.Recent().Files().value(0), QDir::cleanPath(QFileInfo(Geb079Path()).absoluteFilePath()));
      window.close();
    }
    MainWindow reopened;
    QCOMPARE(reopened.Recent().Files().value(0), QDir::cleanPath(QFileInfo(Geb079Path()).absoluteFilePath()));
  }

  void FailedOpenIsNotRecent() {
    MainWindow window;
    window.OpenMap(QStringLiteral("/nonexistent/map.ot"));
    QVERIFY(window.Maps()->LastError().contains(QStringLiteral("/nonexistent/map.ot")));
    QVERIFY(window.Recent().Files().isEmpty());
  }

  void ExploreOptionsRunAMissionInTheMissionWorkspace() {
    QTemporaryDir dir;
    MainWindow window;
    window.show();
    QVERIFY(QTest::qWaitForWindowExposed(&window));
    MissionSession* session = window.Mission()->Session();
    std::vector<MissionPhase> phases;
    connect(session, &MissionSession::PhaseChanged, this,
            [&phases](MissionPhase phase) { phases.push_back(phase); });
    const QString world = ResourcePath(QStringLiteral("worlds/small_office.yaml"));
    GuiOptions options;
    options.explore_world = world.toStdString();
    options.explore_out = dir.path().toStdString();
    options.explore_max_time_s = 1.0;       // The shortest the panel takes.
    options.explore_poses = "groundtruth";  // Not the panel's default (slam).
    options.explore_kinect_width = 160;     // Not the panel's default (320); also quicker.

    ApplyStartOptions(window, options);
    QCOMPARE(window.CurrentWorkspace(), window.WorkspaceNames().indexOf(QStringLiteral("Mission")));
    const runtime::MissionConfig config = window.Mission()->Panel()->BuildConfig();
    QCOMPARE(QString::fromStdString(config.world_file), QFileInfo(world).absoluteFilePath());
    QCOMPARE(QString::fromStdString(config.out_dir), dir.path());
    QCOMPARE(config.max_time_s, 1.0);
    QCOMPARE(config.poses, runtime::PoseSource::kGroundTruth);
    QCOMPARE(config.kinect_width, 160);
    QCOMPARE(config.kinect_height, 120);
    QCOMPARE(session->Phase(), MissionPhase::kStarting);
    QTRY_VERIFY_WITH_TIMEOUT(
        session->Phase() == MissionPhase::kFinished || session->Phase() == MissionPhase::kFailed,
        60000);  // About 10 s on two busy cores.
    QVERIFY2(session->Phase() == MissionPhase::kFinished, qPrintable(session->LastError()));
    QVERIFY(std::find(phases.begin(), phases.end(), MissionPhase::kRunning) != phases.end());
    QVERIFY(session->Report().has_value());
    QFile report_file(dir.filePath(QStringLiteral("report.json")));
    QVERIFY(report_file.open(QIODevice::ReadOnly));
    const QJsonObject report = QJsonDocument::fromJson(report_file.readAll()).object();
    QCOMPARE(report.value(QStringLiteral("poses")).toString(), QStringLiteral("groundtruth"));
    QCOMPARE(report.value(QStringLiteral("kinect_width")).toInt(), 160);
    QVERIFY(window.isVisible());  // The results stay on screen until the operator closes.
  }

  void ExploreOfAMissingWorldFailsBeforeAnyWindowOpens() {
    QProcess dynamap;
    dynamap.start(QStringLiteral(DYNAMAP_EXECUTABLE),
                  {QStringLiteral("gui"), QStringLiteral("--explore"),
                   QStringLiteral("/nonexistent/world.yaml")});
    QVERIFY(dynamap.waitForFinished(20000));  // A window would keep it running.
    QCOMPARE(dynamap.exitStatus(), QProcess::NormalExit);
    QCOMPARE(dynamap.exitCode(), 2);
    const QString error = QString::fromLocal8Bit(dynamap.readAllStandardError());
    QVERIFY2(error.startsWith(QStringLiteral("dynamap gui: error: /nonexistent/world.yaml")),
             qPrintable(error));
  }

  void RecentFilesDeduplicateAndCap() {
    RecentFiles recent(3);
    for (const char* name : {"/a.ot", "/b.ot", "/c.ot", "/a.ot", "/d.ot"}) {
      recent.Add(QString::fromLatin1(name));
    }
    QCOMPARE(recent.Files(), (QStringList{QStringLiteral("/d.ot"), QStringLiteral("/a.ot"),
                                          QStringLiteral("/c.ot")}));
    QSettings settings;
    recent.Save(settings);
    RecentFiles loaded(3);
    loaded.Load(settings);
    QCOMPARE(loaded.Files(), recent.Files());
  }
};

std::unique_ptr<QObject> MakeMainWindowTest() { return std::make_unique<MainWindowTest>(); }

}  // namespace dynamap::app::gui::test

#include "MainWindowTest.moc"
