// Renders each workspace in the main window with real content and saves PNGs into the
// build tree (screenshots/gui/): a short simulated mission on the small office (160×120
// Kinects), the calibration wizard in the simulated room, and in the Maps workspace
// geb079.bt and a synthetic dual map with a person in the dynamic layer. Checks that the
// pictures hold what they should (voxels, red dynamic ones).
#include <QDir>
#include <QImage>
#include <QSignalSpy>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

#include "GuiTestSupport.hpp"
#include "dynamap/app/gui/CalibrationResults.hpp"
#include "dynamap/app/gui/CalibrationWorkspace.hpp"
#include "dynamap/app/gui/RigView.hpp"
#include "dynamap/app/gui/DepthPreview.hpp"
#include "dynamap/app/gui/MainWindow.hpp"
#include "dynamap/app/gui/MapControls.hpp"
#include "dynamap/app/gui/MapsWorkspace.hpp"
#include "dynamap/app/gui/MissionPanel.hpp"
#include "dynamap/app/gui/MissionWorkspace.hpp"
#include "dynamap/app/gui/ResourceFiles.hpp"
#include "dynamap/app/gui/VoxelView.hpp"

namespace dynamap::app::gui::test {

namespace {

// Pixels that are clearly the dynamic layer's red, not the background or viridis; the
// orientation axes in the lower left corner (red x axis) are left out.
int RedPixels(const QImage& image) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      if (x < image.width() / 4 && y > image.height() * 2 / 3) continue;
      const QColor c = image.pixelColor(x, y);
      if (c.red() > 120 && c.red() > 2 * c.green() && c.red() > 2 * c.blue()) ++count;
    }
  }
  return count;
}

// Distinct colours in a coarse grid: an empty view has a gradient and nothing else.
int DistinctColours(const QImage& image) {
  QSet<QRgb> colours;
  for (int y = 0; y < image.height(); y += 4) {
    for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y) & 0xF0F0F0u);
  }
  return colours.size();
}

}  // namespace

class ScreenshotTest : public QObject {
  Q_OBJECT

 private slots:
  void initTestCase() {
    out_dir_ = OutputDir(QStringLiteral("screenshots/gui"));
    window_ = std::make_unique<MainWindow>();
    window_->resize(1400, 860);
    window_->show();
    QVERIFY(QTest::qWaitForWindowExposed(window_.get()));
  }
  void cleanupTestCase() { window_.reset(); }

  void ShortMission() {
    QTemporaryDir out;
    window_->ShowWorkspace(1);
    MissionWorkspace* mission = window_->Mission();
    mission->Panel()->SetWorldFile(ResourcePath(QStringLiteral("worlds/small_office.yaml")));
    mission->Panel()->SetKinectSize(160, 120);
    mission->Panel()->SetPoseSource(runtime::PoseSource::kGroundTruth);
    // Long enough for the first look around (about 13 s) and some driving, so the trail
    // and the planned path are in the picture.
    mission->Panel()->SetTimeLimit(30.0);
    mission->Panel()->SetSavePeriod(1.0);
    mission->Panel()->SetOutputDir(out.path());
    QVERIFY(mission->StartMission());
    QTRY_COMPARE_WITH_TIMEOUT(mission->Session()->Phase(), MissionPhase::kFinished, 90000);
    QTRY_VERIFY_WITH_TIMEOUT(mission->Session()->Map() != nullptr, 20000);
    QTest::qWait(300);
    const QImage view = mission->View()->grabFramebuffer();
    const QImage whole = window_->grab().toImage();
    view.save(QDir(out_dir_).filePath(QStringLiteral("mission_small_office_view.png")));
    whole.save(QDir(out_dir_).filePath(QStringLiteral("mission_small_office.png")));
    QVERIFY(DistinctColours(view) > 20);
    QVERIFY(!mission->Depth(0)->Image().isNull());
    QVERIFY(mission->Session()->Snapshot().distance_m > 1.0);  // It drove: a trail to see.
  }

  void CalibrationWizard() {
    QTemporaryDir out;
    window_->ShowWorkspace(0);
    CalibrationWorkspace* calibration = window_->Calibration();
    calibration->SetWorldFile(ResourcePath(QStringLiteral("worlds/calibration_room.yaml")));
    calibration->SetImageWidth(320);
    calibration->SetSpeed(0.0);
    calibration->SetOutputDir(out.path());
    QSignalSpy started(calibration, &CalibrationWorkspace::SessionStarted);
    calibration->BeginSession(calibration->BuildSetup());
    QVERIFY(started.wait(20000));
    QTRY_VERIFY_WITH_TIMEOUT(calibration->LastState().progress.complete, 30000);
    calibration->Next();
    QTRY_COMPARE_WITH_TIMEOUT(calibration->LastState().progress.step,
                              calibration::SessionStep::kTurn, 5000);
    calibration->DriveStep();
    QTRY_VERIFY_WITH_TIMEOUT(calibration->LastState().progress.turned_left_deg > 60.0, 60000);
    QTest::qWait(300);
    window_->grab().toImage().save(
        QDir(out_dir_).filePath(QStringLiteral("calibration_turn_step.png")));
    calibration->Solve();
    QTRY_COMPARE_WITH_TIMEOUT(calibration->LastState().progress.step,
                              calibration::SessionStep::kReview, 60000);
    QTRY_VERIFY_WITH_TIMEOUT(calibration->Results()->Table()->rowCount() > 0, 5000);
    QTest::qWait(300);
    window_->grab().toImage().save(
        QDir(out_dir_).filePath(QStringLiteral("calibration_review.png")));
    calibration->EndSession();
  }

  // The whole guided sequence as recorded by hand (the calibration room's teleop script,
  // 160 px) replayed and solved: the estimated rig on the robot in 3D.
  void CalibrationFromARecording() {
    window_->ShowWorkspace(0);
    QTemporaryDir out;
    const QString recording = out.filePath(QStringLiteral("recording"));
    QVERIFY(RecordCalibrationRoom(recording, 89));
    CalibrationWorkspace* calibration = window_->Calibration();
    calibration->SetRecording(recording);
    calibration->SetSpeed(0.0);
    calibration->SetOutputDir(out.path());
    QSignalSpy started(calibration, &CalibrationWorkspace::SessionStarted);
    calibration->BeginSession(calibration->BuildSetup());
    QVERIFY(started.wait(20000));
    QTRY_VERIFY_WITH_TIMEOUT(calibration->LastState().replay_fraction >= 1.0, 240000);
    calibration->Solve();
    QTRY_COMPARE_WITH_TIMEOUT(calibration->LastState().progress.step,
                              calibration::SessionStep::kReview, 60000);
    QTRY_VERIFY_WITH_TIMEOUT(calibration->Results()->Table()->rowCount() > 0, 5000);
    calibration->Results()->ShowRigTab();
    QTest::qWait(500);
    const QImage rig = calibration->Results()->Rig3d()->grabFramebuffer();
    rig.save(QDir(out_dir_).filePath(QStringLiteral("calibration_rig_3d_view.png")));
    window_->grab().toImage().save(
        QDir(out_dir_).filePath(QStringLiteral("calibration_recording_rig_3d.png")));
    QVERIFY(DistinctColours(rig) > 20);
    calibration->EndSession();
  }

  void Geb079() {
    window_->ShowWorkspace(2);
    Open(Geb079Path());
    const QImage view = Save(QStringLiteral("maps_geb079"));
    QVERIFY(DistinctColours(view) > 50);
  }

  void DualMapWithPerson() {
    Open(WriteOfficeScene(dir_.path()));
    const QImage view = Save(QStringLiteral("maps_dual_office"));
    QVERIFY(RedPixels(view) > 200);
  }

  void DualMapSliceByOccupancy() {
    MapControls* controls = window_->Maps()->Controls();
    controls->SetColourMode(ColourMode::kOccupancy);
    controls->SetSlice(0.0, 1.0);
    const QImage view = Save(QStringLiteral("maps_dual_office_slice"));
    QVERIFY(RedPixels(view) > 100);
    controls->SetColourMode(ColourMode::kHeight);
  }

  void DualMapWithoutDynamicLayer() {
    MapControls* controls = window_->Maps()->Controls();
    controls->SetSlice(-10.0, 10.0);
    controls->SetShowDynamic(false);
    const QImage view = Save(QStringLiteral("maps_dual_office_static_only"));
    QCOMPARE(RedPixels(view), 0);
    controls->SetShowDynamic(true);
  }

 private:
  void Open(const QString& file) {
    QVERIFY(!file.isEmpty());
    window_->OpenMap(file);
    QTRY_VERIFY_WITH_TIMEOUT(!window_->Maps()->Busy(), 60000);
    QVERIFY2(window_->Maps()->Map() != nullptr, qPrintable(window_->Maps()->LastError()));
  }

  // Saves the whole window and the 3D view alone; returns the view.
  QImage Save(const QString& name) {
    QTest::qWait(200);  // Let queued repaints land before grabbing.
    const QImage view = window_->Maps()->View()->grabFramebuffer();
    const QImage whole = window_->grab().toImage();
    view.save(QDir(out_dir_).filePath(name + QStringLiteral("_view.png")));
    whole.save(QDir(out_dir_).filePath(name + QStringLiteral(".png")));
    return view;
  }

  QTemporaryDir dir_;
  QString out_dir_;
  std::unique_ptr<MainWindow> window_;
};

std::unique_ptr<QObject> MakeScreenshotTest() { return std::make_unique<ScreenshotTest>(); }

}  // namespace dynamap::app::gui::test

#include "ScreenshotTest.moc"
