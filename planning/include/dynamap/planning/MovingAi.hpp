// Reader for the Moving AI grid benchmark files (Sturtevant 2012): octile .map grids and
// .scen problem lists, so the planners can be checked against published optimal lengths.
#pragma once

#include <string>
#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/planning/TraversalGrid.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::planning {

struct MovingAiMap {
  int width = 0;
  int height = 0;
  std::vector<bool> passable;  // Row-major, (0,0) top-left; '.' and 'G' pass, all else blocks.
};

struct MovingAiProblem {
  int bucket = 0;
  GridIndex start;
  GridIndex goal;
  double optimal_length = 0.0;  // Cells, 8-connected, diagonal √2, no corner cutting.
};

// Errors name the file and the line and say what was expected.
[[nodiscard]] robotio::Expected<MovingAiMap> LoadMovingAiMap(const std::string& file);
[[nodiscard]] robotio::Expected<std::vector<MovingAiProblem>> LoadMovingAiScenario(
    const std::string& file);
// The same from text already in memory; `name` stands for the file in messages.
[[nodiscard]] robotio::Expected<MovingAiMap> ParseMovingAiMap(const std::string& text,
                                                              const std::string& name);
[[nodiscard]] robotio::Expected<std::vector<MovingAiProblem>> ParseMovingAiScenario(
    const std::string& text, const std::string& name);

[[nodiscard]] TraversalGrid ToTraversalGrid(const MovingAiMap& map);

}  // namespace dynamap::planning
