#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <sstream>

#include "ReferenceIntegrator.hpp"
#include "SyntheticScene.hpp"
#include "ThesisRuleConfig.hpp"
#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/mapping/MapFiles.hpp"
#include "dynamap/mapping/ScanIntegrator.hpp"
#include "dynamap/mapping/UpdateRules.hpp"

namespace dynamap::mapping {
namespace {

std::string Serialise(const DualOcTree& tree) {
  std::ostringstream out;
  tree.write(out);
  return out.str();
}

// One scan of a single end point; every voxel on the way is observed free.
robotio::DepthRays SingleRay(const Eigen::Vector3f& origin, const Eigen::Vector3f& end, bool hit) {
  robotio::DepthRays rays;
  rays.origin = origin;
  rays.ends.push_back(end);
  rays.hit.push_back(hit);
  return rays;
}

// An empty scene scanned, then a box appearing in it: both channels hold something.
void ScanABoxAppearing(DualMap& map, testing::SyntheticScene& scene) {
  map.InsertRays(testing::CastScan(scene, {0, 0, 0}, 4.0f, 2.0f));
  scene.boxes.push_back({{1.5f, -0.2f, -0.5f}, {1.8f, 0.2f, 1.2f}});
  map.InsertRays(testing::CastScan(scene, {0, 0, 0}, 4.0f, 2.0f));
}

TEST(DualOcTreeTest, SaveLoadRoundTripKeepsBothChannelsExactly) {
  DualMap map{ThesisRuleConfig()};
  testing::SyntheticScene scene;
  ScanABoxAppearing(map, scene);
  ASSERT_TRUE(map.IsDynamicOccupied({1.52f, 0.0f, 0.0f}));

  const std::string file = ::testing::TempDir() + "/dual_roundtrip.ot";
  ASSERT_TRUE(SaveDualMap(map.tree(), file));
  auto loaded = LoadMap(file);
  ASSERT_TRUE(loaded) << loaded.error().message;
  EXPECT_EQ((*loaded)->size(), map.tree().size());
  EXPECT_EQ(Serialise(**loaded), Serialise(map.tree()));
  // Compare node by node too: both channels of every leaf.
  std::size_t leaves = 0;
  for (auto it = map.tree().begin_leafs(); it != map.tree().end_leafs(); ++it, ++leaves) {
    const DualOcTreeNode* other = (*loaded)->search(it.getKey(), it.getDepth());
    ASSERT_NE(other, nullptr);
    EXPECT_EQ(other->StaticLogOdds(), it->StaticLogOdds());
    EXPECT_EQ(other->DynamicLogOdds(), it->DynamicLogOdds());
  }
  EXPECT_GT(leaves, 100u);
}

TEST(DualOcTreeTest, CloneIsAnIndependentCopyOfBothChannels) {
  DualMap map{ThesisRuleConfig()};
  testing::SyntheticScene scene;
  ScanABoxAppearing(map, scene);
  ASSERT_TRUE(map.IsDynamicOccupied({1.52f, 0.0f, 0.0f}));
  const std::unique_ptr<DualOcTree> copy = map.tree().Clone();
  EXPECT_EQ(copy->size(), map.tree().size());
  EXPECT_EQ(Serialise(*copy), Serialise(map.tree()));  // Every node, both channels.
  EXPECT_EQ(copy->getProbHit(), map.tree().getProbHit());
  EXPECT_EQ(copy->getClampingThresMax(), map.tree().getClampingThresMax());
  // The original goes on changing; the copy does not.
  const std::string before = Serialise(*copy);
  scene.boxes.clear();
  map.InsertRays(testing::CastScan(scene, {0, 0, 0}, 4.0f, 2.0f));
  EXPECT_NE(Serialise(map.tree()), before);
  EXPECT_EQ(Serialise(*copy), before);
}

TEST(DualOcTreeTest, InnerNodesHoldTheMaximumOfBothChannels) {
  DualMap map{ThesisRuleConfig()};
  testing::SyntheticScene scene;
  map.InsertRays(testing::CastScan(scene, {0, 0, 0}, 4.0f, 2.0f));
  scene.boxes.push_back({{1.5f, -0.2f, -0.5f}, {1.8f, 0.2f, 1.2f}});
  map.InsertRays(testing::CastScan(scene, {0, 0, 0}, 4.0f, 2.0f));
  const DualOcTree& tree = map.tree();
  const DualOcTreeNode* root = tree.getRoot();
  float max_static = -1e9f, max_dynamic = -1e9f;
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    max_static = std::max(max_static, it->StaticLogOdds());
    max_dynamic = std::max(max_dynamic, it->DynamicLogOdds());
  }
  EXPECT_EQ(root->StaticLogOdds(), max_static);
  EXPECT_EQ(root->DynamicLogOdds(), max_dynamic);
  EXPECT_GT(max_dynamic, 0.0f);
}

// Trap: eight equal leaves are pruned into one inner node. Observing one of them must
// expand it so that only that voxel changes, in both channels.
TEST(DualOcTreeTest, ObservingOneVoxelOfAPrunedNodeChangesOnlyThatVoxel) {
  DualMap map{ThesisRuleConfig()};
  DualOcTree& tree = map.tree();
  // Eight known-free leaves of one 2x2x2 cube at the origin, pruned into their parent.
  const octomap::OcTreeKey corner = tree.coordToKey(octomap::point3d(0.01f, 0.01f, 0.01f));
  DualOcTreeNode* node = tree.CreateRoot();
  for (unsigned depth = 0; depth < 15; ++depth) {
    node = tree.createNodeChild(node, octomap::computeChildIdx(corner, static_cast<int>(15 - depth)));
  }
  for (unsigned i = 0; i < 8; ++i) {
    DualOcTreeNode* leaf = tree.createNodeChild(node, i);
    leaf->SetStaticLogOdds(-0.4f);
    leaf->SetDynamicLogOdds(-0.4f);
  }
  tree.updateInnerOccupancy();
  tree.prune();
  ASSERT_FALSE(tree.nodeHasChildren(node));

  // A hit in the corner voxel, the ray coming from -x (outside the cube).
  const octomap::point3d target = tree.keyToCoord(corner);
  map.InsertRays(SingleRay({-1.0f, target.y(), target.z()}, {target.x(), target.y(), target.z()}, true));
  const DualOcTreeNode* hit = tree.search(corner);
  ASSERT_NE(hit, nullptr);
  EXPECT_FLOAT_EQ(hit->StaticLogOdds(), -0.4f + map.rules().low);    // Free + hit: Low.
  EXPECT_FLOAT_EQ(hit->DynamicLogOdds(), -0.4f + map.rules().high);  // Free + hit: High.
  EXPECT_TRUE(tree.IsDynamicOccupied(*hit));
  for (unsigned i = 1; i < 8; ++i) {
    const octomap::OcTreeKey sibling(corner[0] + (i & 1u), corner[1] + ((i >> 1) & 1u),
                                     corner[2] + ((i >> 2) & 1u));
    const DualOcTreeNode* other = tree.search(sibling);
    ASSERT_NE(other, nullptr);
    EXPECT_EQ(other->StaticLogOdds(), -0.4f);
    EXPECT_EQ(other->DynamicLogOdds(), -0.4f);
  }
}

TEST(DualOcTreeTest, PrunedNodesExpandCorrectlyWhenBuiltDirectly) {
  // Eight equal children pruned by OctoMap's own prune(): the parent carries both values.
  DualOcTree tree(0.1);
  DualOcTreeNode* root = tree.CreateRoot();
  DualOcTreeNode* node = root;
  for (unsigned d = 0; d < 15; ++d) node = tree.createNodeChild(node, 0);
  for (unsigned i = 0; i < 8; ++i) {
    DualOcTreeNode* leaf = tree.createNodeChild(node, i);
    leaf->SetStaticLogOdds(-1.0f);
    leaf->SetDynamicLogOdds(2.0f);
  }
  tree.updateInnerOccupancy();
  tree.prune();
  EXPECT_FALSE(tree.nodeHasChildren(node));
  EXPECT_EQ(node->StaticLogOdds(), -1.0f);
  EXPECT_EQ(node->DynamicLogOdds(), 2.0f);
  tree.expandNode(node);
  for (unsigned i = 0; i < 8; ++i) EXPECT_EQ(tree.getNodeChild(node, i)->DynamicLogOdds(), 2.0f);
}

// Trap: OctoMap's updateNode returns early when the occupancy is clamped. A static value
// at its clamp must not stop the dynamic channel from changing.
TEST(DualOcTreeTest, ClampedStaticValueDoesNotStopTheDynamicUpdate) {
  DualMap map{ThesisRuleConfig()};
  const Eigen::Vector3f origin(0, 0, 0), end(1.025f, 0.025f, 0.025f);
  // Observed free many times: the static value sits at the lower clamp.
  for (int i = 0; i < 30; ++i) map.InsertRays(SingleRay(origin, end * 2.0f, false));
  const DualOcTree& tree = map.tree();
  const DualOcTreeNode* node = tree.search(end.x(), end.y(), end.z());
  ASSERT_NE(node, nullptr);
  ASSERT_EQ(node->StaticLogOdds(), map.rules().clamp_min);
  map.InsertRays(SingleRay(origin, end, true));
  node = tree.search(end.x(), end.y(), end.z());
  EXPECT_EQ(node->StaticLogOdds(), map.rules().clamp_min);
  EXPECT_FLOAT_EQ(node->DynamicLogOdds(), map.rules().clamp_min + map.rules().high);
}

TEST(DualOcTreeTest, HitBeatsTraversalWithinOneScan) {
  DualMap map{ThesisRuleConfig()};
  const Eigen::Vector3f origin(0, 0, 0);
  robotio::DepthRays rays;
  rays.origin = origin;
  rays.ends = {Eigen::Vector3f(1.02f, 0.02f, 0.02f), Eigen::Vector3f(2.02f, 0.02f, 0.02f)};
  rays.hit = {true, true};
  map.InsertRays(rays);
  // The first end voxel lies on the second ray: still a hit (unknown + occupied = static).
  EXPECT_TRUE(map.IsStaticOccupied({1.02f, 0.02f, 0.02f}));
  EXPECT_TRUE(map.IsStaticOccupied({2.02f, 0.02f, 0.02f}));
  EXPECT_EQ(map.StaticState({0.52f, 0.02f, 0.02f}), VoxelState::kFree);
}

// Both Kinects of one instant are one scan: a voxel seen from both origins is updated
// once, and a hit from either beats a traversal by the other.
TEST(DualOcTreeTest, AScanFromTwoOriginsUpdatesEachVoxelOnce) {
  DualMap map{ThesisRuleConfig()};
  // Both rays cross x = 1.02 at y = 0.02 (z = 0.02); the first one ends there.
  std::vector<robotio::DepthRays> scan = {
      SingleRay({0.02f, -0.98f, 0.02f}, {1.02f, 0.02f, 0.02f}, true),
      SingleRay({0.02f, 1.02f, 0.02f}, {2.02f, -0.98f, 0.02f}, true)};
  map.InsertScan(scan);
  const DualOcTreeNode* crossing = map.tree().search(1.02, 0.02, 0.02);
  ASSERT_NE(crossing, nullptr);
  EXPECT_FLOAT_EQ(crossing->StaticLogOdds(), map.rules().high);  // Hit, not traversed.
  // Two origins whose rays share their last voxels before a common end (on the floor
  // plane, whose own rule is tested below).
  MappingConfig no_floor = ThesisRuleConfig();
  no_floor.floor_plane = false;
  DualMap shared{no_floor};
  scan = {SingleRay({0.02f, 0.02f, 0.02f}, {2.02f, 0.02f, 0.02f}, true),
          SingleRay({0.02f, 0.02f, 0.22f}, {2.02f, 0.02f, 0.02f}, true)};
  shared.InsertScan(scan);
  const DualOcTreeNode* traversed = shared.tree().search(1.87, 0.02, 0.02);
  ASSERT_NE(traversed, nullptr);
  EXPECT_FLOAT_EQ(traversed->StaticLogOdds(), shared.rules().low);  // One observation.
  // Inserted one after the other, the same voxel is observed twice.
  DualMap separate{no_floor};
  for (const robotio::DepthRays& rays : scan) separate.InsertRays(rays);
  EXPECT_FLOAT_EQ(separate.tree().search(1.87, 0.02, 0.02)->StaticLogOdds(),
                  2.0f * separate.rules().low);
}

// The lasting-change rule counts scans (instants), not Kinect frames: a change both
// Kinects see does not turn static twice as fast.
TEST(DualOcTreeTest, ALastingChangeCountsScansNotKinects) {
  MappingConfig config;
  config.persistence_observations = 40;
  const Eigen::Vector3f low(0.02f, 0.02f, 0.02f), high(0.02f, 0.02f, 0.52f);
  const Eigen::Vector3f door(1.02f, 0.02f, 0.02f);
  // Free space through the door voxel first (both rays cross it to a wall), then closed.
  const std::vector<robotio::DepthRays> open = {SingleRay(low, {2.02f, 0.02f, 0.02f}, true),
                                                SingleRay(high, {2.02f, 0.02f, -0.48f}, true)};
  const std::vector<robotio::DepthRays> closed = {SingleRay(low, door, true),
                                                  SingleRay(high, door, true)};
  DualMap as_scans{config}, per_kinect{config};
  for (int i = 0; i < 20; ++i) {
    as_scans.InsertScan(open);
    for (const auto& rays : open) per_kinect.InsertRays(rays);
  }
  ASSERT_EQ(as_scans.StaticState(door), VoxelState::kFree);
  for (int i = 0; i < 35; ++i) {
    as_scans.InsertScan(closed);
    for (const auto& rays : closed) per_kinect.InsertRays(rays);
  }
  EXPECT_TRUE(as_scans.IsDynamicOccupied(door));
  EXPECT_FALSE(as_scans.IsStaticOccupied(door));
  EXPECT_TRUE(per_kinect.IsStaticOccupied(door));  // 70 observations.
  for (int i = 0; i < 25; ++i) as_scans.InsertScan(closed);
  EXPECT_TRUE(as_scans.IsStaticOccupied(door));
  EXPECT_FALSE(as_scans.IsDynamicOccupied(door));
}

TEST(DualOcTreeTest, RaysBeyondMaxRangeClearUpToItWithoutAHit) {
  MappingConfig config = ThesisRuleConfig();  // One pass: free at once.
  config.max_range_m = 2.0;
  DualMap map{config};
  map.InsertPointCloud({Eigen::Vector3f(3.02f, 0.02f, 0.02f)}, Eigen::Vector3f(0, 0, 0));
  EXPECT_EQ(map.StaticState({1.52f, 0.02f, 0.02f}), VoxelState::kFree);
  EXPECT_EQ(map.StaticState({3.02f, 0.02f, 0.02f}), VoxelState::kUnknown);
  EXPECT_EQ(map.StaticState({2.52f, 0.02f, 0.02f}), VoxelState::kUnknown);
}

TEST(DualOcTreeTest, EndOfARayCutAtMaxRangeStaysUnknownAtABlockBoundary) {
  // The cut end (x in [0.40, 0.45)) is the first voxel of a new 8x8x8 block that no other
  // voxel of the scan touches: it must not turn into a node (a pruned, occupied cube).
  DualMap map{ThesisRuleConfig()};
  map.InsertRays(SingleRay({0.02f, 0.02f, 0.02f}, {0.42f, 0.02f, 0.02f}, false));
  EXPECT_EQ(map.tree().search(0.42, 0.02, 0.02), nullptr);
  EXPECT_FALSE(map.IsStaticOccupied({0.47f, 0.22f, 0.32f}));
  EXPECT_EQ(map.StaticState({0.37f, 0.02f, 0.02f}), VoxelState::kFree);
}

// The floor at z = 0 lies on a voxel boundary: a grazing ray to a floor point just below
// it crosses the layer above for decimetres. x in [2.35, 2.40), z in [0, 0.05) is such a
// floor voxel, crossed by the ray from (0.02, 0.02, 0.5) to (2.52, 0.02, -0.004).
const Eigen::Vector3f kFloorVoxel(2.375f, 0.025f, 0.025f);

robotio::DepthRays GrazingFloorRay() {
  robotio::DepthRays rays = SingleRay({0.02f, 0.02f, 0.5f}, {2.52f, 0.02f, -0.004f}, true);
  rays.incidence_cos = {0.504f / 2.55f};  // Elevation of the ray above the floor.
  return rays;
}

DualMap MapWithHitFloorVoxel(const MappingConfig& config) {
  DualMap map{config};
  robotio::DepthRays down = SingleRay({2.37f, 0.02f, 0.5f}, {2.37f, 0.02f, 0.01f}, true);
  down.incidence_cos = {1.0f};
  map.InsertRays(down);
  return map;
}

TEST(DualOcTreeTest, EdgeClearanceSparesRaysThatPassOverAHolesEdgeIntoIt) {
  MappingConfig config;
  config.edge_clearance_voxels = 1.0;
  const UpdateRules rules = UpdateRules::FromConfig(config);
  // Both rays pass 1.2 m from the origin beside a nearer surface (the floor at a pit's edge
  // or a door post). One ends below the floor, in the pit: it keeps its free space, which
  // is what shows the planner the hole. The other ends on a wall behind the post and is cut
  // the surface margin before the post.
  robotio::DepthRays rays;
  rays.origin = {0.0f, 0.0f, 0.6f};
  rays.ends = {{2.0f, 0.0f, -0.6f}, {2.0f, 0.0f, 0.3f}};
  rays.hit = {true, true};
  rays.incidence_cos = {1.0f, 1.0f};
  rays.surface_range_m = {(rays.ends[0] - rays.origin).norm(), (rays.ends[1] - rays.origin).norm()};
  rays.alongside_range_m = {1.2f, 1.2f};
  const std::optional<Eigen::Vector3f> into_pit = FreeSpaceEnd(rays, 0, rules);
  ASSERT_TRUE(into_pit.has_value());
  EXPECT_LT(into_pit->z(), -0.5f);
  const std::optional<Eigen::Vector3f> past_post = FreeSpaceEnd(rays, 1, rules);
  ASSERT_TRUE(past_post.has_value());
  EXPECT_NEAR((*past_post - rays.origin).norm(), 1.2f - rules.surface_margin_m, 1e-5f);
}

TEST(DualOcTreeTest, GrazingRaysDoNotClearTheFloorTheySkim) {
  DualMap map = MapWithHitFloorVoxel(MappingConfig{});
  ASSERT_TRUE(map.IsStaticOccupied(kFloorVoxel));
  for (int scan = 0; scan < 8; ++scan) map.InsertRays(GrazingFloorRay());
  EXPECT_TRUE(map.IsStaticOccupied(kFloorVoxel));
  // Well above the floor the same ray is still free-space evidence.
  EXPECT_EQ(map.StaticState({1.02f, 0.02f, 0.28f}), VoxelState::kFree);
}

TEST(DualOcTreeTest, WithoutTheSurfaceMarginGrazingRaysClearTheFloor) {
  MappingConfig config;
  config.surface_margin_voxels = 0.0;  // OctoMap's rule: free up to the end voxel.
  config.surface_band = false;
  config.floor_plane = false;
  DualMap map = MapWithHitFloorVoxel(config);
  for (int scan = 0; scan < 8; ++scan) map.InsertRays(GrazingFloorRay());
  EXPECT_EQ(map.StaticState(kFloorVoxel), VoxelState::kFree);
}

TEST(DualOcTreeTest, VoxelsNextToAHitAreNotObservedFreeInThatScan) {
  for (const bool band : {true, false}) {
    MappingConfig config = ThesisRuleConfig();  // One free observation makes a voxel free.
    config.surface_band = band;
    DualMap map{config};
    robotio::DepthRays rays;
    rays.origin = Eigen::Vector3f(0.02f, 0.02f, 0.02f);
    // The first ray ends next to a voxel the second one crosses (no incidence known).
    rays.ends = {Eigen::Vector3f(2.02f, 0.07f, 0.02f), Eigen::Vector3f(3.02f, 0.02f, 0.02f)};
    rays.hit = {true, true};
    map.InsertRays(rays);
    EXPECT_EQ(map.StaticState({2.02f, 0.02f, 0.02f}),
              band ? VoxelState::kUnknown : VoxelState::kFree) << "band " << band;
    EXPECT_EQ(map.StaticState({1.52f, 0.02f, 0.02f}), VoxelState::kFree);
    EXPECT_TRUE(map.IsStaticOccupied({2.02f, 0.07f, 0.02f}));
  }
}

// The floor seen from the rig's height (1 m), a strip of points at z = 0.01 from 0.5 m to
// 3.5 m ahead, each with its incidence on the horizontal floor.
robotio::DepthRays FloorStrip() {
  robotio::DepthRays rays;
  rays.origin = Eigen::Vector3f(0.02f, 0.02f, 1.0f);
  for (float x = 0.5f; x < 3.5f; x += 0.01f) {
    rays.ends.emplace_back(x, 0.02f, 0.01f);
    rays.hit.push_back(true);
    rays.incidence_cos.push_back(0.99f / std::hypot(x - 0.02f, 0.99f));
  }
  return rays;
}

TEST(DualOcTreeTest, TheLayerAboveTheFloorIsSeenFreeTheFloorStaysOccupied) {
  for (const bool floor_plane : {true, false}) {
    MappingConfig config = ThesisRuleConfig();  // One free observation makes a voxel free.
    config.floor_plane = floor_plane;
    DualMap map{config};
    map.InsertRays(FloorStrip());
    int free_above = 0;
    int voxels = 0;
    for (float x = 1.025f; x < 3.0f; x += 0.05f) {
      ++voxels;
      EXPECT_TRUE(map.IsStaticOccupied({x, 0.025f, 0.025f})) << "floor at x " << x;
      free_above += map.StaticState({x, 0.025f, 0.075f}) == VoxelState::kFree ? 1 : 0;
    }
    // Where a person's feet stood is seen empty again; without the rule it never is.
    if (floor_plane) {
      EXPECT_GE(free_above, voxels - 2);
    } else {
      EXPECT_EQ(free_above, 0);
    }
    EXPECT_EQ(map.StaticState({2.025f, 0.025f, 0.175f}), VoxelState::kFree);
  }
}

TEST(DualOcTreeTest, FeetAboveTheFloorLeaveTheDynamicMapWhenTheyHaveGone) {
  DualMap map{MappingConfig{}};
  for (int scan = 0; scan < 10; ++scan) map.InsertRays(FloorStrip());
  // A foot (a box 0.1 m high) at x = 2 m, seen for a while, then gone.
  const Eigen::Vector3f foot(2.025f, 0.025f, 0.075f);
  robotio::DepthRays with_foot = FloorStrip();
  for (std::size_t i = 0; i < with_foot.ends.size(); ++i) {
    const float x = with_foot.ends[i].x();
    if (x >= 2.0f && x < 2.3f) {
      // The ray meets the foot's top or front: end it at the foot's voxel layer.
      with_foot.ends[i] = Eigen::Vector3f(2.0f + 0.01f * (x - 2.0f), 0.02f, 0.07f);
    }
  }
  for (int scan = 0; scan < 10; ++scan) map.InsertRays(with_foot);
  ASSERT_EQ(map.DynamicState(foot), VoxelState::kOccupied);
  for (int scan = 0; scan < 10; ++scan) map.InsertRays(FloorStrip());
  EXPECT_NE(map.DynamicState(foot), VoxelState::kOccupied);
  EXPECT_TRUE(map.IsStaticOccupied({2.025f, 0.025f, 0.025f}));  // The floor under it.
}

TEST(DualOcTreeTest, NeverObservedVoxelsAreUnknown) {
  DualMap map{ThesisRuleConfig()};
  EXPECT_EQ(map.StaticState({1, 1, 1}), VoxelState::kUnknown);
  EXPECT_EQ(map.DynamicState({1, 1, 1}), VoxelState::kUnknown);
  map.InsertRays(SingleRay({0, 0, 0}, {1.02f, 0.02f, 0.02f}, true));
  EXPECT_EQ(map.StaticState({0.02f, 1.02f, 0.02f}), VoxelState::kUnknown);
}

// The batched update equals the plain reference on a scene with a person moving through
// it, in both modes, scan after scan (structure, pruning and every value), from one
// origin and from two per scan (the two Kinects of the rig).
TEST(DualOcTreeTest, BatchedUpdateEqualsTheReferenceImplementation) {
  for (UpdateMode mode : {UpdateMode::kDynamic, UpdateMode::kRegular}) {
    for (const int origins : {1, 2}) {
      MappingConfig config;
      config.update = mode;
      config.resolution_m = 0.1;
      DualMap fast{config};
      DualOcTree reference(config.resolution_m);
      testing::SyntheticScene scene;
      for (int scan = 0; scan < 12; ++scan) {
        scene.boxes = {{{1.5f, -1.0f + 0.15f * scan, -0.5f}, {1.8f, -0.6f + 0.15f * scan, 1.2f}}};
        const Eigen::Vector3f origin(0.05f * scan, 0.01f * scan, 0.3f);
        std::vector<robotio::DepthRays> rays = {testing::CastScan(scene, origin, 4.0f, 1.0f)};
        if (origins == 2) {
          rays.push_back(
              testing::CastScan(scene, origin + Eigen::Vector3f(0.1f, 0.05f, 0.5f), 4.0f, 1.0f));
          fast.InsertScan(rays);
        } else {
          fast.InsertRays(rays.front());
        }
        testing::ReferenceInsert(reference, rays, fast.rules());
        ASSERT_EQ(fast.tree().size(), reference.size()) << origins << " origins, scan " << scan;
        ASSERT_EQ(Serialise(fast.tree()), Serialise(reference)) << origins << " origins, scan " << scan;
      }
    }
  }
}

// Threads share a scan's rays (MappingConfig::insert_threads) and merge what they observed:
// the map is byte for byte the one-thread map, scan after scan, with scans large enough
// (about 68,000 rays per origin) to be split.
TEST(DualOcTreeTest, TheMapDoesNotDependOnTheNumberOfInsertThreads) {
  std::vector<std::vector<robotio::DepthRays>> scans;
  testing::SyntheticScene scene;
  for (int scan = 0; scan < 6; ++scan) {
    scene.boxes = {{{1.5f, -1.0f + 0.15f * scan, -0.5f}, {1.8f, -0.6f + 0.15f * scan, 1.2f}}};
    const Eigen::Vector3f origin(0.05f * scan, 0.01f * scan, 0.3f);
    scans.push_back({testing::CastScan(scene, origin, 4.0f, 0.2f),
                     testing::CastScan(scene, origin + Eigen::Vector3f(0.1f, 0.05f, 0.5f), 4.0f,
                                       0.2f)});
  }
  ASSERT_GT(scans.front().front().ends.size(), 60000u);
  MappingConfig config;
  config.resolution_m = 0.05;
  config.insert_threads = 1;
  DualMap one_thread{config};
  for (const int threads : {2, 3}) {
    config.insert_threads = threads;
    DualMap several{config};
    for (std::size_t scan = 0; scan < scans.size(); ++scan) {
      const ScanStatistics expected = threads == 2 ? one_thread.InsertScan(scans[scan])
                                                   : ScanStatistics{};
      const ScanStatistics got = several.InsertScan(scans[scan]);
      if (threads == 2) {
        EXPECT_EQ(got.hit_voxels, expected.hit_voxels);
        EXPECT_EQ(got.free_voxels, expected.free_voxels);
        // Each thread traces its own distinct ends: a few are traced by both.
        EXPECT_GE(got.traced_rays, expected.traced_rays);
        ASSERT_EQ(Serialise(several.tree()), Serialise(one_thread.tree()))
            << threads << " threads, scan " << scan;
      }
    }
    EXPECT_EQ(Serialise(several.tree()), Serialise(one_thread.tree())) << threads << " threads";
  }
}

}  // namespace
}  // namespace dynamap::mapping
