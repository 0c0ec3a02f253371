#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "SyntheticScene.hpp"
#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/mapping/MapEvaluation.hpp"
#include "dynamap/mapping/MapExport.hpp"
#include "dynamap/mapping/Preprocessing.hpp"

namespace dynamap::mapping {
namespace {

// `scans` frames of the (still) `scene` inserted from a level 160 x 120 camera at
// `position`, looking along `yaw`: rendered once, inserted that many times.
void LookFrom(DualMap& map, const testing::SyntheticScene& scene, const Eigen::Vector3f& position,
              float yaw, int scans) {
  const robotio::Intrinsics k = robotio::Intrinsics{}.Scaled(160, 120);
  const robotio::KinectMount mount = testing::LevelMount(k);
  const robotio::DepthFrame frame = testing::RenderDepth(scene, position, yaw, k);
  for (int scan = 0; scan < scans; ++scan) {
    map.InsertDepthFrame(frame, mount, testing::BasePose(position, yaw));
  }
}

// The robot watches a wall; after a few empty scans a person walks across and stops.
DualMap WalkThrough(UpdateMode mode) {
  MappingConfig config;
  config.update = mode;
  DualMap map{config};
  testing::SyntheticScene scene;
  const Eigen::Vector3f origin(0.0f, 0.0f, 0.3f);
  for (int scan = 0; scan < 5; ++scan) map.InsertRays(testing::CastScan(scene, origin, 4.0f));
  for (int step = 0; step <= 13; ++step) {
    const float y = -1.0f + 0.1f * step;  // Ends at y in [0.3, 0.6], in view.
    scene.boxes = {{{1.6f, y, -0.5f}, {1.9f, y + 0.3f, 1.2f}}};
    map.InsertRays(testing::CastScan(scene, origin, 4.0f));
  }
  for (int scan = 0; scan < 3; ++scan) map.InsertRays(testing::CastScan(scene, origin, 4.0f));
  return map;
}

TEST(DynamicSceneTest, PersonWalkingThroughEndsInTheDynamicMapNotTheStaticOne) {
  const DualMap map = WalkThrough(UpdateMode::kDynamic);
  const Eigen::Vector3f person_front(1.62f, 0.42f, 0.32f);  // Where the person stands now.
  EXPECT_TRUE(map.IsDynamicOccupied(person_front));
  EXPECT_FALSE(map.IsStaticOccupied(person_front));
  const Eigen::Vector3f passed(1.62f, -0.48f, 0.32f);  // Where the person walked through.
  EXPECT_FALSE(map.IsStaticOccupied(passed));
  const Eigen::Vector3f wall(3.02f, 0.52f, 0.32f);
  EXPECT_TRUE(map.IsStaticOccupied(wall));
  EXPECT_FALSE(map.IsDynamicOccupied(wall));
}

// A door leaf 4 cm thick, first seen edge-on from a camera in its plane, then face-on from
// the side (the office's S1 door, seen from the corridor and then from the room).
DualMap EdgeOnThenFaceOn(double edge_clearance_voxels) {
  MappingConfig config;
  config.edge_clearance_voxels = edge_clearance_voxels;
  DualMap map{config};
  testing::SyntheticScene scene;
  scene.boxes = {{{1.0f, 0.32f, -0.5f}, {2.0f, 0.36f, 1.0f}}};
  LookFrom(map, scene, {0.0f, 0.34f, 0.3f}, 0.0f, 10);   // In the leaf's plane.
  LookFrom(map, scene, {0.2f, 1.3f, 0.3f}, -0.6f, 10);   // Beside it.
  return map;
}

TEST(DynamicSceneTest, AThinLeafSeenEdgeOnStaysInTheStaticMap) {
  const DualMap map = EdgeOnThenFaceOn(1.0);
  // The voxel holding the leaf's far face (y = 0.36) half-way along it.
  const Eigen::Vector3f leaf(1.52f, 0.37f, 0.32f);
  EXPECT_TRUE(map.IsStaticOccupied(leaf));
  EXPECT_FALSE(map.IsDynamicOccupied(leaf));
}

TEST(DynamicSceneTest, WithoutTheEdgeClearanceRaysAlongAThinLeafSendItToTheDynamicMap) {
  const DualMap map = EdgeOnThenFaceOn(0.0);
  const Eigen::Vector3f leaf(1.52f, 0.37f, 0.32f);
  EXPECT_FALSE(map.IsStaticOccupied(leaf));
  EXPECT_TRUE(map.IsDynamicOccupied(leaf));
}

// A wall ending at a doorway (x = 2.6), its face (y = 0.41) 1 cm into the voxel layer
// [0.40, 0.45): first seen face-on, then from the corridor 0.6 m off its plane looking
// along `yaw`. The camera drops what it sees at more than 75 deg.
DualMap FaceOnThenFromTheCorridor(const MappingConfig& config, float yaw) {
  DualMap map{config};
  testing::SyntheticScene scene;
  scene.wall_x = 6.0f;
  scene.drop_below_incidence_cos = 0.26f;
  scene.boxes = {{{0.5f, 0.29f, -0.5f}, {2.6f, 0.41f, 2.0f}}};
  LookFrom(map, scene, {2.2f, 1.6f, 0.3f}, -1.5708f, 10);  // Facing the wall.
  LookFrom(map, scene, {0.0f, 1.01f, 0.3f}, yaw, 20);      // From the corridor.
  return map;
}

// Looking past the wall's end: the face beyond 2.24 m is seen at more than 75 deg, and the
// rays past the end run through the layer's air beside the last metre.
DualMap FaceOnThenAlongTheWall(double grazing_gap_deg) {
  MappingConfig config;
  config.grazing_gap_deg = grazing_gap_deg;
  return FaceOnThenFromTheCorridor(config, std::atan2(0.41f - 1.01f, 2.6f));
}

TEST(DynamicSceneTest, AWallFaceSeenAlongFromACorridorStaysStatic) {
  const DualMap map = FaceOnThenAlongTheWall(MappingConfig{}.grazing_gap_deg);
  for (const float x : {2.425f, 2.475f, 2.525f, 2.575f}) {
    const Eigen::Vector3f face(x, 0.42f, 0.32f);
    EXPECT_TRUE(map.IsStaticOccupied(face)) << x;
  }
}

TEST(DynamicSceneTest, WithoutFillingGrazingGapsTheRaysPastTheWallEndClearItsFace) {
  const DualMap map = FaceOnThenAlongTheWall(0.0);
  int cleared = 0;
  for (const float x : {2.425f, 2.475f, 2.525f, 2.575f}) {
    cleared += map.IsStaticOccupied({x, 0.42f, 0.32f}) ? 0 : 1;
  }
  EXPECT_GE(cleared, 2);
}

// Turned so that the wall's end lies just outside the image's right edge: the rays along
// that edge (12.75 deg right of x; the end is at 13.0 deg) pass the end through the
// layer's air with nothing measured beside them.
DualMap FaceOnThenPastTheEndBesideTheView(double unseen_side_depth_m) {
  MappingConfig config;
  config.unseen_side_depth_m = unseen_side_depth_m;
  const robotio::Intrinsics k = robotio::Intrinsics{}.Scaled(160, 120);
  const float half_view = std::atan2(static_cast<float>(k.width - 1 - k.cx),
                                     static_cast<float>(k.fx));
  return FaceOnThenFromTheCorridor(config, half_view - 12.75f * 3.14159265f / 180.0f);
}

TEST(DynamicSceneTest, AWallEndJustBesideTheViewStaysStaticWithASurfaceAssumedThere) {
  const DualMap map = FaceOnThenPastTheEndBesideTheView(1.5);
  EXPECT_TRUE(map.IsStaticOccupied({2.575f, 0.42f, 0.32f}));
  EXPECT_TRUE(map.IsStaticOccupied({2.525f, 0.42f, 0.32f}));
}

TEST(DynamicSceneTest, ByDefaultNothingIsAssumedBesideTheViewAndTheEdgeRaysClearTheWallEnd) {
  const DualMap map = FaceOnThenPastTheEndBesideTheView(MappingConfig{}.unseen_side_depth_m);
  EXPECT_FALSE(map.IsStaticOccupied({2.575f, 0.42f, 0.32f}));
}

// A camera 0.3 m above the floor (z = 0) facing a wall 1.5 m away: from 15 deg below the
// horizon down the floor is seen at more than 75 deg and dropped, a gap of 9 rows above the
// wall's foot. Returns, for the ray of the wall's lowest measured pixel in the middle
// column, the range where it passes the nearest surface beside it over its own range.
float AlongsideOfTheWallsFootOverItsRange(bool floor_plane) {
  MappingConfig config;
  config.floor_plane = floor_plane;
  const DualMap map{config};
  testing::SyntheticScene scene;
  scene.wall_x = 1.5f;
  scene.floor_z = 0.0f;
  scene.drop_below_incidence_cos = 0.26f;
  const robotio::Intrinsics k = robotio::Intrinsics{}.Scaled(160, 120);
  const Eigen::Vector3f camera(0.0f, 0.0f, 0.3f);
  const robotio::DepthFrame frame = testing::RenderDepth(scene, camera, 0.0f, k);
  const robotio::DepthRays rays =
      map.RaysOf(frame, testing::LevelMount(k), testing::BasePose(camera, 0.0f));
  // Image rows grow downwards: the wall's foot is the last wall row before the gap.
  const auto wall_depth = static_cast<std::uint16_t>(1500);
  int foot = -1;
  for (int v = 0; v < frame.height; ++v) {
    if (frame.At(80, v) == wall_depth) foot = v;
  }
  EXPECT_GT(foot, 0);
  EXPECT_EQ(frame.At(80, foot + 1), 0);  // The gap.
  std::size_t i = 0;  // The foot pixel's index among the measured pixels.
  for (int v = 0; v < foot; ++v) {
    for (int u = 0; u < frame.width; ++u) i += frame.At(u, v) >= 300 ? 1 : 0;
  }
  for (int u = 0; u < 80; ++u) i += frame.At(u, foot) >= 300 ? 1 : 0;
  return rays.alongside_range_m[i] / (rays.ends[i] - rays.origin).norm();
}

TEST(DynamicSceneTest, TheFarFloorsGapFillsNothingWithTheFloorPlane) {
  // With the floor plane the floor's grazing pixels seed no gap: the wall's foot has
  // nothing nearer beside it. Without it the gap takes the floor's last measured depth
  // (about 1.1 m) and the foot's ray stops there.
  EXPECT_NEAR(AlongsideOfTheWallsFootOverItsRange(true), 1.0f, 0.01f);
  EXPECT_LT(AlongsideOfTheWallsFootOverItsRange(false), 0.85f);
}

// A person stands 3.87 m deep, 25 degrees beside the camera's axis (4.27 m along the ray),
// then walks off; the wall behind lies beyond the 4 m max range.
DualMap PersonAtTheEdgeOfRangeWalksOff() {
  DualMap map{MappingConfig{}};
  testing::SyntheticScene scene;
  scene.wall_x = 8.0f;
  scene.boxes = {{{3.87f, 1.6f, -0.5f}, {4.15f, 1.95f, 1.2f}}};
  const Eigen::Vector3f origin(0.0f, 0.0f, 0.3f);
  LookFrom(map, scene, origin, 0.0f, 5);
  scene.boxes.clear();
  LookFrom(map, scene, origin, 0.0f, 20);
  return map;
}

TEST(DynamicSceneTest, APersonAtTheEdgeOfRangeBesideTheAxisLeavesTheStaticMap) {
  const DualMap map = PersonAtTheEdgeOfRangeWalksOff();
  // The person's face: a hit by depth, which the rays cut at max range must see free again
  // (cut at 4 m along the ray, they stopped 3.63 m deep there and it stayed static).
  const Eigen::Vector3f face(3.88f, 1.77f, 0.32f);
  EXPECT_EQ(map.StaticState(face), VoxelState::kFree);
  // Beyond the max-range depth nothing is known.
  EXPECT_EQ(map.StaticState({4.12f, 0.02f, 0.32f}), VoxelState::kUnknown);
}

TEST(DynamicSceneTest, RegularUpdateKeepsThePersonInTheMap) {
  const DualMap map = WalkThrough(UpdateMode::kRegular);
  EXPECT_TRUE(map.IsStaticOccupied({1.62f, 0.42f, 0.32f}));
  EXPECT_FALSE(map.IsDynamicOccupied({1.62f, 0.42f, 0.32f}));
  EXPECT_TRUE(map.IsStaticOccupied({3.02f, 0.52f, 0.32f}));
}

TEST(DynamicSceneTest, PreprocessingDropsPointsInDynamicVoxels) {
  const DualMap map = WalkThrough(UpdateMode::kDynamic);
  // Base frame = map frame here (identity pose).
  const robotio::PointList points = {Eigen::Vector3f(1.62f, 0.42f, 0.32f),
                                     Eigen::Vector3f(3.02f, 0.52f, 0.32f)};
  const robotio::PointList kept = RemoveDynamicPoints(points, map, Eigen::Isometry3d::Identity());
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_EQ(kept[0], points[1]);
}

TEST(DynamicSceneTest, PointsInSeenFreeSpaceAreDroppedBeforeTheDynamicMapKnowsThem) {
  // Only the empty room seen: a person stepping in now is in space seen free.
  MappingConfig config;
  DualMap map{config};
  testing::SyntheticScene scene;
  const Eigen::Vector3f origin(0.0f, 0.0f, 0.3f);
  robotio::DepthRays rays = testing::CastScan(scene, origin, 4.0f);
  for (std::size_t i = 0; i < rays.ends.size(); ++i) {  // Incidence on the wall or the floor.
    const Eigen::Vector3f d = (rays.ends[i] - origin).normalized();
    const bool on_wall = std::abs(rays.ends[i].x() - scene.wall_x) < 1e-3f;
    rays.incidence_cos.push_back(rays.hit[i] ? std::abs(on_wall ? d.x() : d.z()) : 1.0f);
  }
  for (int scan = 0; scan < 5; ++scan) map.InsertRays(rays);
  const robotio::PointList points = {
      Eigen::Vector3f(1.62f, 0.42f, 0.32f),   // The person, in free space.
      Eigen::Vector3f(3.02f, 0.52f, 0.32f),   // The wall.
      Eigen::Vector3f(2.97f, 0.52f, 0.32f)};  // The wall predicted 5 cm in front of it.
  EXPECT_EQ(RemoveDynamicPoints(points, map, Eigen::Isometry3d::Identity()).size(), 3u);
  const robotio::PointList kept = RemovePointsOfChange(points, map, Eigen::Isometry3d::Identity());
  ASSERT_EQ(kept.size(), 2u);
  EXPECT_EQ(kept[0], points[1]);
  EXPECT_EQ(kept[1], points[2]);
}

TEST(DynamicSceneTest, VoxelGridLeavesOnePointPerVoxel) {
  robotio::PointList points;
  for (int i = 0; i < 10; ++i) points.emplace_back(0.01f + 0.001f * i, 0.01f, 0.01f);
  points.emplace_back(0.51f, 0.01f, 0.01f);
  const robotio::PointList filtered = VoxelGridFilter(points, 0.1);
  ASSERT_EQ(filtered.size(), 2u);
}

TEST(DynamicSceneTest, PointAccuracyScoresKeptStaticAndRemovedDynamicPoints) {
  const DualMap map = WalkThrough(UpdateMode::kDynamic);
  // A tiny 2x1 depth frame seeing the wall (static) and the person (dynamic), from a
  // kinect at the origin looking along map x (optical z).
  robotio::DepthFrame depth;
  depth.width = 2;
  depth.height = 1;
  depth.intrinsics.fx = depth.intrinsics.fy = 1.0;
  depth.intrinsics.cx = 0.0;
  depth.intrinsics.cy = 0.0;
  robotio::KinectMount mount;
  mount.T_base_kinect.linear() = robotio::BodyFromOptical();
  mount.T_base_kinect.translation() = Eigen::Vector3d(0.0, 0.0, 0.32);
  // Pixel u=0: straight ahead to the wall; u=1 would look right (-y): not used for depth.
  depth.depth_mm = {3020, 0};
  robotio::LabelFrame labels;
  labels.width = 2;
  labels.height = 1;
  labels.labels = {1, 0};
  PointAccuracyCounter counter(map.config().resolution_m, 4.0, 1);
  counter.Add(depth, labels, mount, Eigen::Isometry3d::Identity());
  // The person: a second frame from the kinect yawed towards (1.62, 0.42).
  robotio::KinectMount turned = mount;
  const double yaw = std::atan2(0.42, 1.62);
  turned.T_base_kinect.linear() =
      Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix() * robotio::BodyFromOptical();
  depth.depth_mm = {static_cast<std::uint16_t>(std::hypot(1.63, 0.42) * 1000.0), 0};
  labels.labels = {static_cast<std::uint16_t>(2 | robotio::LabelFrame::kDynamicBit), 0};
  counter.Add(depth, labels, turned, Eigen::Isometry3d::Identity());
  const PointAccuracy accuracy = counter.Evaluate(map.tree());
  EXPECT_EQ(accuracy.static_points, 1u);
  EXPECT_EQ(accuracy.dynamic_points, 1u);
  EXPECT_DOUBLE_EQ(accuracy.static_accuracy, 1.0);
  EXPECT_DOUBLE_EQ(accuracy.dynamic_accuracy, 1.0);
  EXPECT_DOUBLE_EQ(accuracy.associated_accuracy, 1.0);
}

// A map holding only the floor voxel at (1.02, 0.02, 0.02).
DualMap MapOfOneFloorVoxel() {
  DualMap map{MappingConfig{}};
  robotio::DepthRays floor;
  floor.origin = Eigen::Vector3f(0.02f, 0.02f, 0.5f);
  floor.ends = {Eigen::Vector3f(1.02f, 0.02f, 0.02f)};
  floor.hit = {true};
  map.InsertRays(floor);
  EXPECT_TRUE(map.IsStaticOccupied({1.02f, 0.02f, 0.02f}));
  return map;
}

// One point of `label` at (1.02, 0.02, z), seen by a one-pixel Kinect looking along map x
// from 1 m away.
void AddPointAtHeight(PointAccuracyCounter& counter, std::uint16_t label, double z) {
  robotio::DepthFrame depth;
  depth.width = depth.height = 1;
  depth.intrinsics.fx = depth.intrinsics.fy = 1.0;
  depth.intrinsics.cx = depth.intrinsics.cy = 0.0;
  depth.depth_mm = {1000};
  robotio::LabelFrame labels;
  labels.width = labels.height = 1;
  labels.labels = {label};
  robotio::KinectMount mount;
  mount.T_base_kinect.linear() = robotio::BodyFromOptical();  // Looking along map x.
  mount.T_base_kinect.translation() = Eigen::Vector3d(0.02, 0.02, z);
  counter.Add(depth, labels, mount, Eigen::Isometry3d::Identity());
}

// Two points of one label against that map: one in the floor voxel, one at
// (1.02, 0.02, 1.02), never mapped.
PointAccuracy FloorPointAndPointAboveIt(std::uint16_t label) {
  const DualMap map = MapOfOneFloorVoxel();
  PointAccuracyCounter counter(map.config().resolution_m, 4.0, 1);
  for (const double z : {0.02, 1.02}) AddPointAtHeight(counter, label, z);
  return counter.Evaluate(map.tree());
}

// A foot in the floor's voxel is kept with the floor: it counts against DA, and the
// near-floor figures say how much of DA that is (the chest above is removed).
TEST(DynamicSceneTest, DynamicPointsInTheFloorLayerAreCountedApart) {
  const PointAccuracy accuracy =
      FloorPointAndPointAboveIt(static_cast<std::uint16_t>(2 | robotio::LabelFrame::kDynamicBit));
  EXPECT_EQ(accuracy.dynamic_points, 2u);
  EXPECT_EQ(accuracy.dynamic_points_near_floor, 1u);
  EXPECT_EQ(accuracy.dynamic_kept_near_floor, 1u);
  EXPECT_DOUBLE_EQ(accuracy.dynamic_accuracy, 0.5);
  EXPECT_DOUBLE_EQ(accuracy.dynamic_accuracy_above_floor, 1.0);
}

// The same split for static points: the floor point is kept, the wall point above never
// made it into the map, and the split says which of the two layers SA misses.
TEST(DynamicSceneTest, StaticPointsInTheFloorLayerAreCountedApart) {
  const PointAccuracy accuracy = FloorPointAndPointAboveIt(1);
  EXPECT_EQ(accuracy.static_points, 2u);
  EXPECT_EQ(accuracy.static_points_near_floor, 1u);
  EXPECT_EQ(accuracy.static_kept_near_floor, 1u);
  EXPECT_DOUBLE_EQ(accuracy.static_accuracy, 0.5);
  EXPECT_DOUBLE_EQ(accuracy.static_accuracy_above_floor, 0.0);
}

// Misclassified() says where SA was lost: the wall point's voxel, never mapped, with the
// one point it stands for; the kept floor point is not listed.
TEST(DynamicSceneTest, MisclassifiedVoxelsNameWhereStaticPointsWereLost) {
  const DualMap map = MapOfOneFloorVoxel();
  PointAccuracyCounter counter(map.config().resolution_m, 4.0, 1);
  for (const double z : {0.02, 1.02, 1.02}) AddPointAtHeight(counter, 1, z);
  // A person's point in the floor voxel: kept with the floor.
  AddPointAtHeight(counter, static_cast<std::uint16_t>(2 | robotio::LabelFrame::kDynamicBit),
                   0.02);

  const MisclassifiedVoxels wrong = counter.Misclassified(map.tree());
  ASSERT_EQ(wrong.static_lost.size(), 1u);
  EXPECT_NEAR(wrong.static_lost[0].x(), 1.025, 1e-3);
  EXPECT_NEAR(wrong.static_lost[0].z(), 1.025, 1e-3);
  EXPECT_EQ(wrong.static_lost_points[0], 2u);
  ASSERT_EQ(wrong.dynamic_kept.size(), 1u);
  EXPECT_NEAR(wrong.dynamic_kept[0].z(), 0.025, 1e-3);
  EXPECT_EQ(wrong.dynamic_kept_points[0], 1u);
  // The same counts as the accuracy figures.
  const PointAccuracy accuracy = counter.Evaluate(map.tree());
  EXPECT_EQ(accuracy.static_points - accuracy.static_kept, 2u);
  EXPECT_EQ(accuracy.dynamic_points - accuracy.dynamic_removed, 1u);

  const std::string csv = MisclassifiedVoxelsCsv(wrong);
  EXPECT_EQ(csv.substr(csv.find('\n') + 1),
            "x,y,z,static_points_lost,dynamic_points_kept\n"
            "1.025,0.025,1.025,2,0\n"
            "1.025,0.025,0.025,0,1\n");
}

TEST(DynamicSceneTest, SurfacePrecisionAndCompletenessAgainstTrueSamples) {
  const DualMap map = WalkThrough(UpdateMode::kDynamic);
  // True wall samples in the sensor's view (and some far outside it).
  robotio::PointList samples;
  for (float y = -2.0f; y <= 2.0f; y += 0.025f) {
    for (float z = -0.5f; z <= 1.6f; z += 0.025f) samples.emplace_back(3.0f, y, z);
  }
  robotio::PointList with_unseen = samples;
  with_unseen.emplace_back(-5.0f, -5.0f, 0.0f);
  const SurfaceAccuracy wall_only = EvaluateStaticSurfaces(map.tree(), with_unseen);
  EXPECT_GT(wall_only.static_map_completeness, 0.95);
  // Precision: the floor is static too but not among these samples, so precision is the
  // wall's share of the static voxels.
  EXPECT_GT(wall_only.static_map_precision, 0.1);
  EXPECT_LT(wall_only.static_map_precision, 0.9);
  for (float x = 0.0f; x <= 3.0f; x += 0.025f) {
    for (float y = -2.0f; y <= 2.0f; y += 0.025f) samples.emplace_back(x, y, -0.5f);
  }
  const SurfaceAccuracy with_floor = EvaluateStaticSurfaces(map.tree(), samples);
  EXPECT_GT(with_floor.static_map_precision, 0.97);
}

}  // namespace
}  // namespace dynamap::mapping
