// Projection through the real dual map: a scan of floor and a wall inserted into
// mapping::DualMap, projected via DualMapView, re-projected on the columns it touched.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>

#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/planning/DualMapView.hpp"

namespace dynamap::planning {
namespace {

// Floor points over x in [0.3, 2.9], y in [-1, 1] and a wall at x = 2.0 for |y| < 0.5,
// seen from a sensor 0.6 m above the origin.
robotio::PointList FloorAndWall() {
  robotio::PointList points;
  for (float x = 0.3f; x < 2.9f; x += 0.02f) {
    for (float y = -1.0f; y < 1.0f; y += 0.02f) {
      if (x > 1.98f && std::abs(y) < 0.5f) continue;  // Behind the wall: not seen.
      points.emplace_back(x, y, -0.01f);
    }
  }
  for (float y = -0.5f; y < 0.5f; y += 0.02f) {
    for (float z = 0.0f; z < 1.2f; z += 0.02f) points.emplace_back(2.01f, y, z);
  }
  return points;
}

TEST(DualMapProjection, FloorIsNavigableWallIsObstacleUnseenIsUnknown) {
  mapping::DualMap map(mapping::MappingConfig{});
  const Eigen::Vector3f origin(0.0f, 0.0f, 0.6f);
  for (int i = 0; i < 3; ++i) map.InsertPointCloud(FloorAndWall(), origin);
  const DualMapView view(map);
  GridMap area(80, 60, view.Resolution());
  area.origin_x_m = -1.0;
  area.origin_y_m = -1.5;
  MapProjector projector(area, ProjectionConfig{});
  const robotio::DepthRays rays = mapping::RaysFromPoints(FloorAndWall(), origin, 4.0);
  const std::vector<Eigen::Vector2f> touched = TouchedColumns(rays, projector.map());
  EXPECT_FALSE(projector.Update(view, touched).empty());
  const GridMap& grid = projector.map();
  EXPECT_EQ(grid.At(grid.CellAt(1.0, 0.3)), CellState::kNavigable);
  EXPECT_EQ(grid.At(grid.CellAt(2.02, 0.0)), CellState::kObstacle);
  EXPECT_EQ(grid.At(grid.CellAt(2.5, 0.0)), CellState::kUnknown);  // In the wall's shadow.
  EXPECT_EQ(grid.At(grid.CellAt(-0.8, -1.3)), CellState::kUnknown);  // No ray went there.
  // The same scan again changes nothing, and only touched columns were looked at.
  EXPECT_TRUE(projector.Update(view, touched).empty());
}

TEST(DualMapProjection, ASavedMapProjectsOverItsOwnExtent) {
  mapping::DualMap map(mapping::MappingConfig{});
  const Eigen::Vector3f origin(0.0f, 0.0f, 0.6f);
  for (int i = 0; i < 3; ++i) map.InsertPointCloud(FloorAndWall(), origin);
  const GridMap grid = ProjectSavedMap(map.tree(), ProjectionConfig{});
  ASSERT_FALSE(grid.cells.empty());
  EXPECT_DOUBLE_EQ(grid.resolution_m, map.tree().getResolution());
  // The extent of what was seen: from the sensor's column to the wall, |y| ≤ 1.
  EXPECT_LE(grid.origin_x_m, 0.0);
  EXPECT_GE(grid.origin_x_m + grid.width * grid.resolution_m, 2.0);
  EXPECT_LE(grid.origin_y_m, -0.95);
  EXPECT_EQ(grid.At(grid.CellAt(1.0, 0.3)), CellState::kNavigable);
  EXPECT_EQ(grid.At(grid.CellAt(2.02, 0.0)), CellState::kObstacle);
  EXPECT_TRUE(ProjectSavedMap(mapping::DualOcTree(0.05), ProjectionConfig{}).cells.empty());
}

TEST(DualMapProjection, TouchedColumnsFollowTheRaysFootprint) {
  GridMap area(40, 40, 0.1);
  robotio::DepthRays rays;
  rays.origin = Eigen::Vector3f(0.05f, 0.05f, 0.5f);
  rays.ends = {Eigen::Vector3f(1.05f, 0.05f, 0.0f)};
  rays.hit = {true};
  const std::vector<Eigen::Vector2f> columns = TouchedColumns(rays, area);
  EXPECT_EQ(columns.size(), 11u);  // Cells x = 0..10 of row 0.
  for (const Eigen::Vector2f& c : columns) EXPECT_NEAR(c.y(), 0.05f, 1e-6f);
}

// A frame's worth of rays (a 1 rad fan, lengths varying as over furniture and floor): the
// columns found are those the rays really cross (each ray walked alone), nearly all of
// them, though only the longest ray per narrow bearing bin is walked.
TEST(DualMapProjection, TouchedColumnsOfAFanAreThoseItsRaysCross) {
  GridMap area(200, 200, 0.05);
  area.origin_x_m = -5.0;
  area.origin_y_m = -5.0;
  robotio::DepthRays fan;
  fan.origin = Eigen::Vector3f(0.01f, 0.02f, 0.6f);
  for (int v = 0; v < 60; ++v) {
    for (int u = 0; u < 160; ++u) {
      const double bearing = -0.5 + u / 160.0 + 0.002 * v;  // Rows bend slightly.
      const double length = 0.6 + 3.8 * ((u * 7 + v * 13) % 100) / 100.0;
      fan.ends.emplace_back(fan.origin.x() + length * std::cos(bearing),
                            fan.origin.y() + length * std::sin(bearing), 0.0f);
      fan.hit.push_back(true);
    }
  }
  std::set<std::pair<float, float>> exact;
  for (std::size_t i = 0; i < fan.ends.size(); ++i) {
    robotio::DepthRays one;
    one.origin = fan.origin;
    one.ends = {fan.ends[i]};
    one.hit = {true};
    for (const Eigen::Vector2f& c : TouchedColumns(one, area)) exact.insert({c.x(), c.y()});
  }
  const std::vector<Eigen::Vector2f> found = TouchedColumns(fan, area);
  std::set<std::pair<float, float>> unique;
  for (const Eigen::Vector2f& c : found) {
    EXPECT_TRUE(exact.count({c.x(), c.y()})) << c.transpose();
    unique.insert({c.x(), c.y()});
  }
  EXPECT_EQ(unique.size(), found.size());  // Each column once.
  EXPECT_GE(static_cast<double>(found.size()), 0.97 * static_cast<double>(exact.size()));
}

TEST(DualMapProjection, HitColumnsAreWhereRaysEndedOnAnObstacle) {
  GridMap area(40, 40, 0.1);
  robotio::DepthRays rays;
  rays.origin = Eigen::Vector3f(0.05f, 0.05f, 0.5f);
  rays.ends = {Eigen::Vector3f(1.05f, 0.05f, 0.0f),    // Floor: below the step height.
               Eigen::Vector3f(2.05f, 0.05f, 0.5f),    // A door.
               Eigen::Vector3f(2.07f, 0.03f, 0.6f),    // The same door column again.
               Eigen::Vector3f(3.05f, 0.05f, 1.5f),    // Above the robot.
               Eigen::Vector3f(3.05f, 1.05f, 0.5f)};   // Cut at max range: no hit.
  rays.hit = {true, true, true, true, false};
  const std::vector<Eigen::Vector2f> columns = HitColumns(rays, area, 0.08, 0.9);
  ASSERT_EQ(columns.size(), 1u);
  EXPECT_NEAR(columns[0].x(), 2.05f, 1e-6f);
  EXPECT_NEAR(columns[0].y(), 0.05f, 1e-6f);
}

}  // namespace
}  // namespace dynamap::planning
