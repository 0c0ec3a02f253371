// Voxel extraction, layer visibility, height slicing and picking, without a window.
#include <QtTest>
#include <octomap/octomap_utils.h>

#include <atomic>
#include <memory>

#include "GuiTestSupport.hpp"
#include "dynamap/app/gui/VoxelSet.hpp"

namespace dynamap::app::gui::test {

namespace {

// Three static voxels, one dynamic voxel and one occupied in both channels, far enough
// apart that nothing prunes.
std::unique_ptr<mapping::DualOcTree> SmallTree() {
  auto tree = std::make_unique<mapping::DualOcTree>(0.1);
  for (const auto& p : {octomap::point3d(0.05f, 0.05f, 0.05f), octomap::point3d(1.05f, 0.05f, 0.05f),
                        octomap::point3d(2.05f, 0.05f, 1.05f)}) {
    tree->updateNode(p, true)->SetDynamicLogOdds(octomap::logodds(0.12));
  }
  tree->updateNode(octomap::point3d(3.05f, 0.05f, 0.55f), false)
      ->SetDynamicLogOdds(octomap::logodds(0.9));
  tree->updateNode(octomap::point3d(4.05f, 0.05f, 0.55f), true)
      ->SetDynamicLogOdds(octomap::logodds(0.8));
  tree->updateInnerOccupancy();
  return tree;
}

VoxelSet Extract(const mapping::DualOcTree& tree) {
  std::atomic<bool> cancel{false};
  auto set = ExtractVoxels(tree, cancel, nullptr);
  return set ? std::move(*set) : VoxelSet{};
}

}  // namespace

class VoxelSetTest : public QObject {
  Q_OBJECT

 private slots:
  void ExtractionCountsEachChannel() {
    const VoxelSet set = Extract(*SmallTree());
    QCOMPARE(set.voxels.size(), std::size_t{5});
    QCOMPARE(set.static_count, std::size_t{4});
    QCOMPARE(set.dynamic_count, std::size_t{2});
    QCOMPARE(set.resolution_m, 0.1);
    QVERIFY(std::abs(set.min_corner.x() - 0.0f) < 1e-4f);
    QVERIFY(std::abs(set.max_corner.x() - 4.1f) < 1e-4f);
    QVERIFY(std::abs(set.max_corner.z() - 1.1f) < 1e-4f);
  }

  void ExtractionKeepsProbabilities() {
    const VoxelSet set = Extract(*SmallTree());
    bool found = false;
    for (const Voxel& v : set.voxels) {
      if (std::abs(v.centre.x() - 3.05f) > 1e-3f) continue;
      found = true;
      QVERIFY(!v.static_occupied);
      QVERIFY(v.dynamic_occupied);
      QVERIFY(std::abs(v.dynamic_probability - 0.9f) < 1e-3f);
      QVERIFY(std::abs(v.size - 0.1f) < 1e-6f);
    }
    QVERIFY(found);
  }

  void CancelledExtractionReturnsNothing() {
    std::atomic<bool> cancel{true};
    QVERIFY(!ExtractVoxels(*SmallTree(), cancel, nullptr).has_value());
  }

  void ExtractionReportsProgressUpToOne() {
    std::atomic<bool> cancel{false};
    double last = -1.0;
    const auto set = ExtractVoxels(*MakeOfficeScene(), cancel, [&last](double f) { last = f; });
    QVERIFY(set.has_value());
    QCOMPARE(last, 1.0);
  }

  void BothChannelVoxelDrawsInDynamicLayerOnly() {
    const VoxelSet set = Extract(*SmallTree());
    const VoxelFilter all;
    QCOMPARE(VisibleIndices(set, VoxelLayer::kStatic, all).size(), std::size_t{3});
    QCOMPARE(VisibleIndices(set, VoxelLayer::kDynamic, all).size(), std::size_t{2});
    VoxelFilter static_only;
    static_only.show_dynamic = false;
    QCOMPARE(VisibleIndices(set, VoxelLayer::kStatic, static_only).size(), std::size_t{4});
    QCOMPARE(VisibleIndices(set, VoxelLayer::kDynamic, static_only).size(), std::size_t{0});
  }

  void HeightSliceKeepsCentresInRange() {
    const VoxelSet set = Extract(*SmallTree());
    VoxelFilter slice;
    slice.z_min = 0.5f;
    slice.z_max = 0.6f;
    QCOMPARE(VisibleIndices(set, VoxelLayer::kStatic, slice).size(), std::size_t{0});
    QCOMPARE(VisibleIndices(set, VoxelLayer::kDynamic, slice).size(), std::size_t{2});
  }

  void PickReturnsNearestVisibleVoxel() {
    const VoxelSet set = Extract(*SmallTree());
    // Along +x at the height of the first two static voxels: the one at x = 0.05 first.
    const auto pick = PickVoxel(set, VoxelFilter{}, Eigen::Vector3f(-1.0f, 0.05f, 0.05f),
                                Eigen::Vector3f(1.0f, 0.0f, 0.0f));
    QVERIFY(pick.has_value());
    QVERIFY(std::abs(set.voxels[pick->index].centre.x() - 0.05f) < 1e-3f);
    QVERIFY(std::abs(pick->distance_m - 1.0f) < 1e-4f);
    QVERIFY(pick->layer == VoxelLayer::kStatic);
  }

  void PickSkipsHiddenVoxelsAndMisses() {
    const VoxelSet set = Extract(*SmallTree());
    VoxelFilter no_static;
    no_static.show_static = false;
    const auto pick = PickVoxel(set, no_static, Eigen::Vector3f(-1.0f, 0.05f, 0.55f),
                                Eigen::Vector3f(2.0f, 0.0f, 0.0f));
    QVERIFY(pick.has_value());
    QVERIFY(pick->layer == VoxelLayer::kDynamic);
    QVERIFY(std::abs(set.voxels[pick->index].centre.x() - 3.05f) < 1e-3f);
    QVERIFY(!PickVoxel(set, VoxelFilter{}, Eigen::Vector3f(-1.0f, 3.0f, 0.05f),
                       Eigen::Vector3f(1.0f, 0.0f, 0.0f))
                 .has_value());
  }
};

std::unique_ptr<QObject> MakeVoxelSetTest() { return std::make_unique<VoxelSetTest>(); }

}  // namespace dynamap::app::gui::test

#include "VoxelSetTest.moc"
