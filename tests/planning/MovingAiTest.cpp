// Both planners against the published optimal lengths of the Moving AI benchmark maps.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "dynamap/planning/AStar.hpp"
#include "dynamap/planning/DStarLite.hpp"
#include "dynamap/planning/MovingAi.hpp"

namespace dynamap::planning {
namespace {

const std::string kDir = std::string(DYNAMAP_SHARED_DATA_DIR) + "/movingai/";

struct Scenario {
  std::string map;
  int stride;  // Test every stride-th problem.
};

class MovingAiOptimality : public ::testing::TestWithParam<Scenario> {};

TEST_P(MovingAiOptimality, BothPlannersReturnTheOptimalLength) {
  const Scenario& scenario = GetParam();
  auto map = LoadMovingAiMap(kDir + scenario.map);
  ASSERT_TRUE(map) << map.error().message;
  auto problems = LoadMovingAiScenario(kDir + scenario.map + ".scen");
  ASSERT_TRUE(problems) << problems.error().message;
  ASSERT_FALSE(problems->empty());
  const TraversalGrid grid = ToTraversalGrid(*map);
  int checked = 0;
  for (std::size_t i = 0; i < problems->size(); i += scenario.stride) {
    const MovingAiProblem& p = (*problems)[i];
    const double tolerance = 1e-3 * std::max(1.0, p.optimal_length);
    const GridPath astar = AStarSearch(grid, p.start, p.goal);
    ASSERT_TRUE(astar.found) << "A* problem " << i;
    EXPECT_NEAR(astar.cost, p.optimal_length, tolerance) << "A* problem " << i;
    DStarLite dstar(grid, p.start, p.goal);
    const GridPath path = dstar.Plan();
    ASSERT_TRUE(path.found) << "D* Lite problem " << i;
    EXPECT_NEAR(path.cost, p.optimal_length, tolerance) << "D* Lite problem " << i;
    EXPECT_EQ(path.cells.front(), p.start);
    EXPECT_EQ(path.cells.back(), p.goal);
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>((problems->size() + scenario.stride - 1) / scenario.stride));
}

INSTANTIATE_TEST_SUITE_P(Maps, MovingAiOptimality,
                         ::testing::Values(Scenario{"arena.map", 1}, Scenario{"den101d.map", 1},
                                           Scenario{"8room_000.map", 10}),
                         [](const auto& info) {
                           std::string name = info.param.map.substr(0, info.param.map.find('.'));
                           return name;
                         });

TEST(MovingAiReader, MapErrorNamesFileAndLine) {
  const auto map = ParseMovingAiMap("type octile\nheight 2\nwidth 3\nmap\n...\n.x.\n", "m.map");
  ASSERT_FALSE(map);
  EXPECT_NE(map.error().message.find("m.map:6"), std::string::npos) << map.error().message;
  EXPECT_NE(map.error().message.find("'x'"), std::string::npos);
}

TEST(MovingAiReader, ShortRowIsAnError) {
  const auto map = ParseMovingAiMap("type octile\nheight 2\nwidth 3\nmap\n...\n..\n", "m.map");
  ASSERT_FALSE(map);
  EXPECT_NE(map.error().message.find("m.map:6"), std::string::npos) << map.error().message;
}

TEST(MovingAiReader, ReadsPassableCells) {
  const auto map = ParseMovingAiMap("type octile\nheight 2\nwidth 3\nmap\n.@G\nTS.\n", "m.map");
  ASSERT_TRUE(map) << map.error().message;
  EXPECT_EQ(map->width, 3);
  EXPECT_EQ(map->height, 2);
  EXPECT_EQ(map->passable, (std::vector<bool>{true, false, true, false, false, true}));
}

TEST(MovingAiReader, ScenarioErrorNamesFileAndLine) {
  const auto scen = ParseMovingAiScenario(
      "version 1\n0\tm.map\t3\t2\t0\t0\t2\t1\t2.41\n0\tm.map\t3\t2\t0\t0\t9\t1\t2\n", "s.scen");
  ASSERT_FALSE(scen);
  EXPECT_NE(scen.error().message.find("s.scen:3"), std::string::npos) << scen.error().message;
}

TEST(MovingAiReader, MissingFileNamesIt) {
  const auto map = LoadMovingAiMap("/nonexistent/x.map");
  ASSERT_FALSE(map);
  EXPECT_NE(map.error().message.find("/nonexistent/x.map"), std::string::npos);
}

}  // namespace
}  // namespace dynamap::planning
