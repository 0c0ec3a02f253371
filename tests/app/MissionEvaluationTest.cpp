#include <gtest/gtest.h>

#include <opencv2/imgcodecs.hpp>

#include "../robotio/TestPaths.hpp"
#include "dynamap/app/runtime/MissionEvaluation.hpp"
#include "dynamap/app/runtime/MissionOutputs.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::app::runtime {
namespace {

using planning::CellState;

// Two 3 x 2 m rooms joined by a 1 m doorway; the robot starts in the west room.
constexpr const char* kTwoRooms = R"(
name: two_rooms
floor: {min: [0, 0], max: [6, 2]}
robot_start: {x: 1.0, y: 1.0, yaw_deg: 0}
walls:
  - {id: south, from: [0, 0], to: [6, 0], thickness: 0.1, height: 2.5}
  - {id: north, from: [6, 2], to: [0, 2], thickness: 0.1, height: 2.5}
  - {id: west, from: [0, 2], to: [0, 0], thickness: 0.1, height: 2.5}
  - {id: east, from: [6, 0], to: [6, 2], thickness: 0.1, height: 2.5}
  - {id: split_low, from: [3, 0], to: [3, 0.5], thickness: 0.1, height: 2.5}
  - {id: split_high, from: [3, 1.5], to: [3, 2], thickness: 0.1, height: 2.5}
)";

planning::GridMap Area(double resolution) {
  // Map frame = robot start: the world spans x in [-1, 5], y in [-1, 1].
  planning::GridMap area(160, 80, resolution);
  area.origin_x_m = -2.0;
  area.origin_y_m = -2.0;
  return area;
}

int Count(const planning::GridMap& map, CellState state) {
  int n = 0;
  for (const CellState s : map.cells) n += s == state ? 1 : 0;
  return n;
}

TEST(TruthGrid, ReachableFloorIsTheFloorShrunkByTheFootprintThroughTheDoorway) {
  auto world = robotio::sim::ParseWorld(kTwoRooms, "two_rooms.yaml");
  ASSERT_TRUE(world) << world.error().message;
  const TruthGrid truth = BuildTruthGrid(*world, Area(0.05), 0.3, 1.0, 0.0);
  // Each room shrinks by the footprint (0.3 m) plus half a wall (0.05 m) on every side:
  // 2 x (2.3 x 1.3) m² plus the doorway between them, in 0.05 m cells.
  const double area_m2 = Count(truth.reachable, CellState::kNavigable) * 0.05 * 0.05;
  EXPECT_NEAR(area_m2, 2 * 2.3 * 1.3 + 0.7 * 0.4, 0.4);
  // The east room is reached through the doorway.
  const planning::GridIndex east_room = truth.reachable.CellAt(3.5, 0.0);
  EXPECT_EQ(truth.reachable.At(east_room), CellState::kNavigable);
}

TEST(TruthGrid, IgnoresTheStatesOfTheGridItIsGivenAsExtent) {
  auto world = robotio::sim::ParseWorld(kTwoRooms, "two_rooms.yaml");
  ASSERT_TRUE(world) << world.error().message;
  planning::GridMap known = Area(0.05);
  std::fill(known.cells.begin(), known.cells.end(), CellState::kNavigable);
  const TruthGrid from_known = BuildTruthGrid(*world, known, 0.3, 1.0, 0.0);
  const TruthGrid from_empty = BuildTruthGrid(*world, Area(0.05), 0.3, 1.0, 0.0);
  EXPECT_EQ(from_known.reachable.cells, from_empty.reachable.cells);
}

TEST(ExploredFreeFraction, CountsKnownNavigableCellsOfTheReachableFloor) {
  auto world = robotio::sim::ParseWorld(kTwoRooms, "two_rooms.yaml");
  ASSERT_TRUE(world) << world.error().message;
  const TruthGrid truth = BuildTruthGrid(*world, Area(0.05), 0.3, 1.0, 0.0);
  EXPECT_DOUBLE_EQ(ExploredFreeFraction(truth, Area(0.05)), 0.0);
  EXPECT_DOUBLE_EQ(ExploredFreeFraction(truth, truth.reachable), 1.0);
  // Knowing only the west room (map x < 2) is about half.
  planning::GridMap west = truth.reachable;
  for (int y = 0; y < west.height; ++y) {
    for (int x = 0; x < west.width; ++x) {
      if (west.CenterX(x) > 2.0) west.Set({x, y}, CellState::kUnknown);
    }
  }
  EXPECT_NEAR(ExploredFreeFraction(truth, west), 0.5, 0.06);
}

TEST(SurfaceCoverage, CountsSurfacesVisibleFromReachableFloorAndSplitsThemBySeen) {
  auto world = robotio::sim::ParseWorld(kTwoRooms, "two_rooms.yaml");
  ASSERT_TRUE(world) << world.error().message;
  const TruthGrid truth = BuildTruthGrid(*world, Area(0.05), 0.3, 1.0, 0.0);
  // Map frame = robot start (1, 1): the north walls' room faces lie at map y = 0.95.
  const robotio::PointList samples = {
      {0.5f, 0.95f, 0.5f},    // West room, north wall: seen.
      {3.5f, 0.95f, 0.5f},    // East room, through the doorway: not seen.
      {0.5f, 0.95f, 1.5f},    // Above the robot: not counted.
      {0.5f, 0.95f, 0.1f},    // At the floor: not counted.
      {0.5f, 1.05f, 0.5f}};   // The wall's outer face: no floor there to see it from.
  const SurfaceCoverageResult coverage = SurfaceCoverage(
      truth, samples, 1.0, 2.5, [](const Eigen::Vector3f& p) { return p.x() < 2.0f; });
  ASSERT_EQ(coverage.inspected.size(), 1u);
  ASSERT_EQ(coverage.missed.size(), 1u);
  EXPECT_FLOAT_EQ(coverage.inspected[0].x(), 0.5f);
  EXPECT_FLOAT_EQ(coverage.missed[0].x(), 3.5f);
  EXPECT_DOUBLE_EQ(coverage.Fraction(), 0.5);
  EXPECT_DOUBLE_EQ(SurfaceCoverageResult{}.Fraction(), 0.0);
}

TEST(SurfaceCoverage, PictureShowsSeenSurfacesGreenAndMissedOnesRed) {
  auto world = robotio::sim::ParseWorld(kTwoRooms, "two_rooms.yaml");
  ASSERT_TRUE(world) << world.error().message;
  const TruthGrid truth = BuildTruthGrid(*world, Area(0.05), 0.3, 1.0, 0.0);
  const SurfaceCoverageResult coverage{{{0.5f, 0.95f, 0.5f}}, {{3.5f, 0.95f, 0.5f}}};
  const std::string file = test::ScratchDir() + "/coverage.png";
  ASSERT_TRUE(WriteCoveragePicture(truth.reachable, coverage, file));
  const cv::Mat image = cv::imread(file, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  const planning::GridMap& grid = truth.reachable;
  ASSERT_EQ(image.cols, 2 * grid.width);
  const auto pixel = [&](float x, float y) {  // The samples' float coordinates.
    const planning::GridIndex c = grid.CellAt(x, y);
    return image.at<cv::Vec3b>(2 * (grid.height - 1 - c.y), 2 * c.x);  // BGR.
  };
  const cv::Vec3b seen = pixel(0.5f, 0.95f), missed = pixel(3.5f, 0.95f);
  EXPECT_GT(seen[1], 150);
  EXPECT_LT(seen[2], 100);
  EXPECT_GT(missed[2], 150);
  EXPECT_LT(missed[1], 100);
}

TEST(AccuracyPicture, ShowsLostStaticPointsBlueAndKeptDynamicPointsRed) {
  auto world = robotio::sim::ParseWorld(kTwoRooms, "two_rooms.yaml");
  ASSERT_TRUE(world) << world.error().message;
  const TruthGrid truth = BuildTruthGrid(*world, Area(0.05), 0.3, 1.0, 0.0);
  mapping::MisclassifiedVoxels wrong;
  wrong.static_lost = {{0.5f, 0.95f, 0.5f}, {0.5f, 0.95f, 1.0f}};
  wrong.static_lost_points = {400, 600};
  wrong.dynamic_kept = {{3.5f, 0.5f, 0.02f}, {4.5f, 0.5f, 0.02f}};
  wrong.dynamic_kept_points = {3, 3000};
  mapping::PointAccuracy accuracy;
  accuracy.static_accuracy = 0.985;
  accuracy.dynamic_accuracy = 0.97;
  const std::string dir = test::ScratchDir();
  ASSERT_TRUE(WriteAccuracyPicture(truth.reachable, wrong, accuracy, dir + "/accuracy.png"));
  const cv::Mat image = cv::imread(dir + "/accuracy.png", cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  const planning::GridMap& grid = truth.reachable;
  const auto pixel = [&](float x, float y) {
    const planning::GridIndex c = grid.CellAt(x, y);
    return image.at<cv::Vec3b>(2 * (grid.height - 1 - c.y), 2 * c.x);  // BGR.
  };
  // The worst cell of each colour is full; three kept points beside 3000 show, fainter.
  const cv::Vec3b lost = pixel(0.5f, 0.95f), kept = pixel(3.5f, 0.5f), most_kept = pixel(4.5f, 0.5f),
                  clean = pixel(1.0f, 0.5f);
  EXPECT_EQ(lost[0], 255);
  EXPECT_LT(lost[2], 60);
  EXPECT_EQ(most_kept[2], 255);
  EXPECT_GT(kept[2], 120);
  EXPECT_LT(kept[2], 160);
  EXPECT_LT(kept[0], 60);
  EXPECT_EQ(clean[0], clean[2]);  // Untouched cells stay grey.
}

}  // namespace
}  // namespace dynamap::app::runtime
