// The Maps workspace's behaviour: opening files (and the errors that name them), layer
// toggles, the height slice, colour modes, picking, exports and cancelling a load.
#include <QFile>
#include <QImage>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <memory>

#include "GuiTestSupport.hpp"
#include "dynamap/app/gui/MapControls.hpp"
#include "dynamap/app/gui/MapsWorkspace.hpp"
#include "dynamap/app/gui/VoxelView.hpp"
#include "dynamap/mapping/MapFiles.hpp"
#include "dynamap/mapping/PointCloudFiles.hpp"

namespace dynamap::app::gui::test {

namespace {

constexpr int kWorkTimeoutMs = 60000;

// Opens `file` and waits until the workspace is idle again.
void OpenAndWait(MapsWorkspace& workspace, const QString& file) {
  workspace.OpenFile(file);
  QTRY_VERIFY_WITH_TIMEOUT(!workspace.Busy(), kWorkTimeoutMs);
}

}  // namespace

class MapsWorkspaceTest : public QObject {
  Q_OBJECT

 private slots:
  void init() {
    dir_ = std::make_unique<QTemporaryDir>();
    workspace_ = std::make_unique<MapsWorkspace>();
    workspace_->resize(1000, 700);
    workspace_->show();
    QVERIFY(QTest::qWaitForWindowExposed(workspace_.get()));
  }
  void cleanup() {
    workspace_.reset();
    dir_.reset();
  }

  void MissingFileErrorNamesTheFile() {
    QSignalSpy errors(workspace_.get(), &MapsWorkspace::ErrorOccurred);
    const QString file = dir_->filePath(QStringLiteral("no_such_map.ot"));
    workspace_->OpenFile(file);
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.first().first().toString().contains(file));
    QVERIFY(workspace_->Map() == nullptr);
  }

  void GarbageFileErrorNamesTheFile() {
    const QString file = dir_->filePath(QStringLiteral("not_a_map.bt"));
    QFile f(file);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("this is not an octree\n");
    f.close();
    QSignalSpy errors(workspace_.get(), &MapsWorkspace::ErrorOccurred);
    OpenAndWait(*workspace_, file);
    QCOMPARE(errors.count(), 1);
    QVERIFY2(errors.first().first().toString().contains(file),
             qPrintable(errors.first().first().toString()));
    QVERIFY(workspace_->Map() == nullptr);
  }

  void OpensPlainOctoMapAsStaticOnly() {
    QSignalSpy opened(workspace_.get(), &MapsWorkspace::MapOpened);
    OpenAndWait(*workspace_, Geb079Path());
    QCOMPARE(opened.count(), 1);
    const auto map = workspace_->Map();
    QVERIFY(map != nullptr);
    QVERIFY(!map->dual);
    QVERIFY(map->voxels->static_count > 10000);
    QCOMPARE(map->voxels->dynamic_count, std::size_t{0});
    QVERIFY(!workspace_->Controls()->DynamicAvailable());
    QCOMPARE(workspace_->View()->VisibleCount(VoxelLayer::kStatic), map->voxels->static_count);
  }

  void OpensDualMapWithBothLayers() {
    OpenAndWait(*workspace_, WriteOfficeScene(dir_->path()));
    const auto map = workspace_->Map();
    QVERIFY(map != nullptr);
    QVERIFY(map->dual);
    QVERIFY(map->voxels->dynamic_count > 100);
    QVERIFY(workspace_->Controls()->DynamicAvailable());
    QCOMPARE(workspace_->View()->VisibleCount(VoxelLayer::kDynamic), map->voxels->dynamic_count);
  }

  void LayerTogglesHideAndShow() {
    OpenAndWait(*workspace_, WriteOfficeScene(dir_->path()));
    VoxelView* view = workspace_->View();
    const std::size_t static_shown = view->VisibleCount(VoxelLayer::kStatic);
    QVERIFY(static_shown > 0);
    workspace_->Controls()->SetShowStatic(false);
    QCOMPARE(view->VisibleCount(VoxelLayer::kStatic), std::size_t{0});
    QVERIFY(view->VisibleCount(VoxelLayer::kDynamic) > 0);
    workspace_->Controls()->SetShowDynamic(false);
    QCOMPARE(view->VisibleCount(VoxelLayer::kDynamic), std::size_t{0});
    workspace_->Controls()->SetShowStatic(true);
    workspace_->Controls()->SetShowDynamic(true);
    QCOMPARE(view->VisibleCount(VoxelLayer::kStatic), static_shown);
  }

  void HeightSliceShowsOnlyThatBand() {
    OpenAndWait(*workspace_, WriteOfficeScene(dir_->path()));
    VoxelView* view = workspace_->View();
    const std::size_t all = view->VisibleCount(VoxelLayer::kStatic);
    // Above the desk and the person's head, below the cabinet top: walls and cabinet only.
    workspace_->Controls()->SetSlice(1.8, 1.85);
    QVERIFY(view->VisibleCount(VoxelLayer::kStatic) < all);
    QCOMPARE(view->VisibleCount(VoxelLayer::kDynamic), std::size_t{0});
    for (const Voxel& v : workspace_->Map()->voxels->voxels) {
      if (IsVisible(v, VoxelLayer::kStatic, view->Filter())) {
        QVERIFY(v.centre.z() > 1.7f && v.centre.z() < 1.95f);
      }
    }
  }

  void ColourModeFollowsControls() {
    OpenAndWait(*workspace_, Geb079Path());
    workspace_->Controls()->SetColourMode(ColourMode::kOccupancy);
    QVERIFY(workspace_->View()->Colours() == ColourMode::kOccupancy);
    workspace_->Controls()->SetColourMode(ColourMode::kHeight);
    QVERIFY(workspace_->View()->Colours() == ColourMode::kHeight);
  }

  void ClickPicksAVoxelAndShowsItsCoordinates() {
    OpenAndWait(*workspace_, WriteOfficeScene(dir_->path()));
    VoxelView* view = workspace_->View();
    int signals_seen = 0;
    std::optional<VoxelPick> pick;
    connect(view, &VoxelView::VoxelPicked, this, [&](const std::optional<VoxelPick>& p) {
      ++signals_seen;
      pick = p;
    });
    const QPoint centre(view->width() / 2, view->height() / 2);
    QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, centre);
    QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, centre);
    QCOMPARE(signals_seen, 1);
    QVERIFY(pick.has_value());
    const Voxel& voxel = workspace_->Map()->voxels->voxels[pick->index];
    QVERIFY(workspace_->Controls()->PickText().contains(QString::number(voxel.centre.x(), 'f', 3)));
  }

  void ExportsStaticBinaryTreeThatReloads() {
    OpenAndWait(*workspace_, WriteOfficeScene(dir_->path()));
    const QString file = dir_->filePath(QStringLiteral("static.bt"));
    QSignalSpy finished(workspace_.get(), &MapsWorkspace::ExportFinished);
    workspace_->Export(ExportKind::kStaticBinaryTree, file);
    QTRY_VERIFY_WITH_TIMEOUT(!workspace_->Busy(), kWorkTimeoutMs);
    QCOMPARE(finished.count(), 1);
    auto reloaded = mapping::LoadMap(file.toStdString());
    QVERIFY(reloaded.ok());
    std::atomic<bool> cancel{false};
    const auto set = ExtractVoxels(**reloaded, cancel, nullptr);
    QVERIFY(set.has_value());
    QCOMPARE(set->static_count, workspace_->Map()->voxels->static_count);
  }

  void ExportsDynamicPointCloud() {
    OpenAndWait(*workspace_, WriteOfficeScene(dir_->path()));
    const QString file = dir_->filePath(QStringLiteral("dynamic.ply"));
    workspace_->Export(ExportKind::kDynamicPly, file);
    QTRY_VERIFY_WITH_TIMEOUT(!workspace_->Busy(), kWorkTimeoutMs);
    const auto points = mapping::ReadPly(file.toStdString());
    QVERIFY(points.ok());
    QVERIFY(points->size() >= workspace_->Map()->voxels->dynamic_count);
  }

  // The office scene's floor and walls as a ROS map_server map: a .yaml naming its .pgm,
  // free floor white and the walls black.
  void ExportsRosMapServerMap() {
    OpenAndWait(*workspace_, WriteOfficeScene(dir_->path()));
    const QString yaml = dir_->filePath(QStringLiteral("office.yaml"));
    QSignalSpy finished(workspace_.get(), &MapsWorkspace::ExportFinished);
    workspace_->Export(ExportKind::kRosMap, yaml);
    QTRY_VERIFY_WITH_TIMEOUT(!workspace_->Busy(), kWorkTimeoutMs);
    QCOMPARE(finished.count(), 1);
    QFile text(yaml);
    QVERIFY(text.open(QIODevice::ReadOnly));
    const QString contents = QString::fromUtf8(text.readAll());
    QVERIFY2(contents.contains(QStringLiteral("image: office.pgm")), qPrintable(contents));
    QVERIFY(contents.contains(QStringLiteral("resolution: 0.05")));
    const QImage pgm(dir_->filePath(QStringLiteral("office.pgm")));
    QVERIFY(!pgm.isNull());
    int free = 0, occupied = 0;
    for (int y = 0; y < pgm.height(); ++y) {
      for (int x = 0; x < pgm.width(); ++x) {
        const int grey = qGray(pgm.pixel(x, y));
        free += grey > 250 ? 1 : 0;
        occupied += grey < 5 ? 1 : 0;
      }
    }
    QVERIFY2(free > 100 && occupied > 20, qPrintable(QStringLiteral("%1 free, %2 occupied").arg(free).arg(occupied)));
  }

  void ExportErrorNamesTheFile() {
    OpenAndWait(*workspace_, Geb079Path());
    const QString file = dir_->filePath(QStringLiteral("missing_dir/out.pcd"));
    QSignalSpy errors(workspace_.get(), &MapsWorkspace::ErrorOccurred);
    workspace_->Export(ExportKind::kStaticPcd, file);
    QTRY_VERIFY_WITH_TIMEOUT(!workspace_->Busy(), kWorkTimeoutMs);
    QCOMPARE(errors.count(), 1);
    QVERIFY2(errors.first().first().toString().contains(file),
             qPrintable(errors.first().first().toString()));
    QVERIFY(!QFile::exists(file));
  }

  void ExportWithoutMapIsAnError() {
    QSignalSpy errors(workspace_.get(), &MapsWorkspace::ErrorOccurred);
    workspace_->Export(ExportKind::kTopDownPng, dir_->filePath(QStringLiteral("top.png")));
    QCOMPARE(errors.count(), 1);
    QVERIFY(errors.first().first().toString().contains(QStringLiteral("no map is open")));
  }

  void CancelledLoadLeavesNoMap() {
    QSignalSpy opened(workspace_.get(), &MapsWorkspace::MapOpened);
    workspace_->OpenFile(Geb079Path());
    QVERIFY(workspace_->Busy());
    workspace_->CancelWork();
    QVERIFY(!workspace_->Busy());
    // Whatever the worker still finishes is dropped.
    QTest::qWait(1500);
    QCOMPARE(opened.count(), 0);
    QVERIFY(workspace_->Map() == nullptr);
  }

 private:
  std::unique_ptr<QTemporaryDir> dir_;
  std::unique_ptr<MapsWorkspace> workspace_;
};

std::unique_ptr<QObject> MakeMapsWorkspaceTest() { return std::make_unique<MapsWorkspaceTest>(); }

}  // namespace dynamap::app::gui::test

#include "MapsWorkspaceTest.moc"
