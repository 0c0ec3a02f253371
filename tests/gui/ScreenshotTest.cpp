// Renders the Maps workspace in the main window with real maps and saves PNGs into the
// build tree (screenshots/gui/): geb079.bt and a synthetic dual map with a person in the
// dynamic layer. Checks that the pictures hold what they should (voxels, red dynamic ones).
#include <QDir>
#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

#include "GuiTestSupport.hpp"
#include "dynamap/app/gui/MainWindow.hpp"
#include "dynamap/app/gui/MapControls.hpp"
#include "dynamap/app/gui/MapsWorkspace.hpp"
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

  void Geb079() {
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
