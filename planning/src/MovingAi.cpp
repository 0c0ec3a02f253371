#include "dynamap/planning/MovingAi.hpp"

#include <fstream>
#include <sstream>

#include "dynamap/planning/CostField.hpp"

namespace dynamap::planning {

namespace {

robotio::Expected<std::string> ReadWholeFile(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return robotio::Error{file + ": cannot open file for reading"};
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

robotio::Error LineError(const std::string& name, int line, const std::string& message) {
  return robotio::Error{name + ":" + std::to_string(line) + ": " + message};
}

std::vector<std::string> SplitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
  }
  return lines;
}

// "key value" header line with an integer value > 0.
bool ParseHeaderInt(const std::string& line, const std::string& key, int* value) {
  std::istringstream in(line);
  std::string word;
  long number = 0;
  std::string rest;
  if (!(in >> word >> number) || word != key || (in >> rest) || number <= 0 ||
      number > 100000) {
    return false;
  }
  *value = static_cast<int>(number);
  return true;
}

}  // namespace

robotio::Expected<MovingAiMap> ParseMovingAiMap(const std::string& text, const std::string& name) {
  const std::vector<std::string> lines = SplitLines(text);
  MovingAiMap map;
  if (lines.empty() || lines[0] != "type octile") {
    return LineError(name, 1, "expected 'type octile'");
  }
  // Height and width may come in either order in the wild; accept both.
  int height = 0;
  int width = 0;
  for (int i = 1; i <= 2; ++i) {
    if (static_cast<int>(lines.size()) <= i) return LineError(name, i + 1, "missing header line");
    if (!ParseHeaderInt(lines[i], "height", &height) && !ParseHeaderInt(lines[i], "width", &width)) {
      return LineError(name, i + 1, "expected 'height N' or 'width N' with 0 < N <= 100000");
    }
  }
  if (height == 0 || width == 0) return LineError(name, 3, "expected both 'height' and 'width'");
  if (lines.size() < 4 || lines[3] != "map") return LineError(name, 4, "expected 'map'");
  if (static_cast<int>(lines.size()) < 4 + height) {
    return LineError(name, static_cast<int>(lines.size()) + 1,
                     "expected " + std::to_string(height) + " map rows, found " +
                         std::to_string(lines.size() - 4));
  }
  map.width = width;
  map.height = height;
  map.passable.assign(static_cast<std::size_t>(width) * height, false);
  for (int y = 0; y < height; ++y) {
    const std::string& row = lines[4 + y];
    if (static_cast<int>(row.size()) != width) {
      return LineError(name, 5 + y, "expected " + std::to_string(width) + " characters, found " +
                                        std::to_string(row.size()));
    }
    for (int x = 0; x < width; ++x) {
      const char c = row[x];
      switch (c) {
        case '.':
        case 'G':
          map.passable[static_cast<std::size_t>(y) * width + x] = true;
          break;
        case '@':
        case 'O':
        case 'T':
        case 'S':
        case 'W':
          break;
        default:
          return LineError(name, 5 + y, std::string("unexpected character '") + c + "' in column " +
                                            std::to_string(x) + " (allowed: . G @ O T S W)");
      }
    }
  }
  for (std::size_t i = 4 + height; i < lines.size(); ++i) {
    if (!lines[i].empty()) {
      return LineError(name, static_cast<int>(i) + 1, "unexpected text after the map rows");
    }
  }
  return map;
}

robotio::Expected<std::vector<MovingAiProblem>> ParseMovingAiScenario(const std::string& text,
                                                                      const std::string& name) {
  const std::vector<std::string> lines = SplitLines(text);
  if (lines.empty() || (lines[0] != "version 1" && lines[0] != "version 1.0")) {
    return LineError(name, 1, "expected 'version 1'");
  }
  std::vector<MovingAiProblem> problems;
  for (std::size_t i = 1; i < lines.size(); ++i) {
    const int line_no = static_cast<int>(i) + 1;
    if (lines[i].empty()) continue;
    std::istringstream in(lines[i]);
    MovingAiProblem p;
    std::string map_path;
    int width = 0;
    int height = 0;
    std::string rest;
    if (!(in >> p.bucket >> map_path >> width >> height >> p.start.x >> p.start.y >> p.goal.x >>
          p.goal.y >> p.optimal_length) ||
        (in >> rest)) {
      return LineError(name, line_no,
                       "expected 9 fields: bucket map width height start-x start-y goal-x goal-y "
                       "optimal-length");
    }
    const auto inside = [&](GridIndex c) {
      return c.x >= 0 && c.y >= 0 && c.x < width && c.y < height;
    };
    if (width <= 0 || height <= 0 || !inside(p.start) || !inside(p.goal) ||
        p.optimal_length < 0.0) {
      return LineError(name, line_no,
                       "start and goal must lie inside the stated width and height, length >= 0");
    }
    problems.push_back(p);
  }
  return problems;
}

robotio::Expected<MovingAiMap> LoadMovingAiMap(const std::string& file) {
  auto text = ReadWholeFile(file);
  if (!text) return text.error();
  return ParseMovingAiMap(*text, file);
}

robotio::Expected<std::vector<MovingAiProblem>> LoadMovingAiScenario(const std::string& file) {
  auto text = ReadWholeFile(file);
  if (!text) return text.error();
  return ParseMovingAiScenario(*text, file);
}

TraversalGrid ToTraversalGrid(const MovingAiMap& map) {
  return TraversalFromPassable(map.width, map.height, map.passable);
}

}  // namespace dynamap::planning
