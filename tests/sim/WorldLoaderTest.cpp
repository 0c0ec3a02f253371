#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "SimTestWorlds.hpp"
#include "dynamap/robotio/Rig.hpp"
#include "dynamap/robotio/sim/RobotConfig.hpp"
#include "dynamap/robotio/sim/StaticSurfaces.hpp"
#include "dynamap/robotio/sim/WorldLoader.hpp"

namespace dynamap::robotio::sim {
namespace {

namespace fs = std::filesystem;

TEST(WorldLoader, EveryBundledWorldAndScenarioLoads) {
  int count = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(DYNAMAP_RESOURCES_DIR) / "worlds")) {
    if (entry.path().extension() != ".yaml") continue;
    auto world = LoadWorld(entry.path().string());
    ASSERT_TRUE(world.ok()) << world.error().message;
    EXPECT_FALSE(world->walls.empty()) << entry.path();
    ++count;
  }
  EXPECT_GE(count, 6);  // office, small_office and the four scenarios.
}

TEST(WorldLoader, TheOfficeTourDrivesAtLeast100Metres) {
  auto tour = LoadTeleop(std::string(DYNAMAP_RESOURCES_DIR) + "/tours/office_tour.yaml");
  ASSERT_TRUE(tour.ok()) << tour.error().message;
  double metres = 0.0;
  for (const TeleopSegment& s : *tour) metres += std::abs(s.v) * s.duration_s;
  EXPECT_GT(metres, 100.0);
}

TEST(WorldLoader, TeleopFileErrorsNameTheFileAndKey) {
  const std::string file = ::testing::TempDir() + "/dynamap_bad_tour.yaml";
  std::ofstream(file) << "teleop:\n  - {v: 0.5, omega: 0, duration: 3}\n";
  auto tour = LoadTeleop(file);
  ASSERT_FALSE(tour.ok());
  EXPECT_NE(tour.error().message.find(file), std::string::npos) << tour.error().message;
  EXPECT_NE(tour.error().message.find("duration"), std::string::npos) << tour.error().message;
  std::ofstream(file) << "name: empty\nteleop: []\n";
  tour = LoadTeleop(file);
  ASSERT_FALSE(tour.ok());
  EXPECT_NE(tour.error().message.find("at least one segment"), std::string::npos)
      << tour.error().message;
}

TEST(WorldLoader, BundledRobotAndRigLoad) {
  auto robot = LoadRobotConfig(std::string(DYNAMAP_RESOURCES_DIR) + "/robots/segway_rmp50.yaml");
  ASSERT_TRUE(robot.ok()) << robot.error().message;
  auto rig = LoadRig(std::string(DYNAMAP_RESOURCES_DIR) + "/rigs/two_kinects.yaml");
  ASSERT_TRUE(rig.ok()) << rig.error().message;
  ASSERT_EQ(rig->kinects.size(), 2u);
  for (const KinectMount& k : rig->kinects) {
    // Upside down: the optical y axis (image down) points up in base.
    EXPECT_GT(k.T_base_kinect.linear().col(1).z(), 0.9);
  }
  EXPECT_NEAR(rig->kinects[0].T_base_kinect.translation().z(), 0.60, 1e-9);
  EXPECT_NEAR(rig->kinects[1].T_base_kinect.translation().z(), 0.46, 1e-9);
}

TEST(WorldLoader, OfficeHasTheRequiredContent) {
  auto world = LoadWorld(std::string(DYNAMAP_RESOURCES_DIR) + "/worlds/office.yaml");
  ASSERT_TRUE(world.ok()) << world.error().message;
  const Eigen::Vector2d extent = world->floor_max - world->floor_min;
  EXPECT_GE(extent.x(), 25.0);
  EXPECT_GE(extent.y(), 15.0);
  EXPECT_GE(world->people.size(), 3u);
  EXPECT_FALSE(world->holes.empty());
  EXPECT_FALSE(world->doors.empty());
}

void ExpectErrorNames(const std::string& yaml, const std::string& key) {
  auto world = ParseWorld(yaml, "bad_world.yaml");
  ASSERT_FALSE(world.ok());
  EXPECT_NE(world.error().message.find("bad_world.yaml"), std::string::npos) << world.error().message;
  EXPECT_NE(world.error().message.find(key), std::string::npos) << world.error().message;
}

TEST(WorldLoader, ErrorsNameTheFileAndKey) {
  const std::string base = testing::WallWorldYaml(3.0);
  ExpectErrorNames(base + "colour: red\n", "colour");
  ExpectErrorNames(base + "people:\n  - {id: p, speed: 9, path: [{at: [1, 1]}]}\n", "speed");
  ExpectErrorNames(base + "people:\n  - {id: wall, path: [{at: [1, 1]}]}\n", "id");
  ExpectErrorNames(base + "holes:\n  - {id: h, min: [1, 1], max: [0, 2]}\n", "max");
  ExpectErrorNames(base + "furniture:\n  - {id: f, pose: [1, 1, 0], size: [1, 1, 1], "
                          "shape: sofa}\n", "shape");
  ExpectErrorNames(base + "doors:\n  - {id: d, hinge: [1, 1], closed_yaw_deg: 0, "
                          "schedule: [{t: 5, open: false}, {t: 2, open: true}]}\n", "schedule");
  ExpectErrorNames("floor: {min: [0, 0], max: [5, 5]}\n", "robot_start");
}

TEST(StaticSurfaces, FloorWithoutHolesAndFinalPlacementsOnly) {
  const World world = testing::MustParse(testing::WallWorldYaml(
      3.0,
      "holes:\n  - {id: pit, min: [-2, -2], max: [-1, -1]}\n"
      "furniture:\n  - {id: chair, pose: [1, 5, 0], size: [0.5, 0.5, 1], "
      "moves: [{t: 10, pose: [1, -5, 0]}]}\n"));
  const PointList points = SampleStaticSurfaces(world, 0.1);
  ASSERT_FALSE(points.empty());
  int in_pit = 0, at_old_place = 0, at_new_place = 0, on_wall = 0;
  for (const auto& p : points) {
    if (p.x() > -1.95f && p.x() < -1.05f && p.y() > -1.95f && p.y() < -1.05f) ++in_pit;
    if (std::abs(p.x() - 1.0f) < 0.2f && std::abs(p.y() - 5.0f) < 0.2f && p.z() > 0.5f) ++at_old_place;
    if (std::abs(p.x() - 1.0f) < 0.2f && std::abs(p.y() + 5.0f) < 0.2f && p.z() > 0.5f) ++at_new_place;
    if (std::abs(p.x() - 3.0f) < 0.01f && p.z() > 0.1f) ++on_wall;
  }
  EXPECT_EQ(in_pit, 0);
  EXPECT_EQ(at_old_place, 0);
  EXPECT_GT(at_new_place, 0);
  EXPECT_GT(on_wall, 100);
}

}  // namespace
}  // namespace dynamap::robotio::sim
