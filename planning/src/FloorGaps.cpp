#include "dynamap/planning/FloorGaps.hpp"

#include <cmath>
#include <cstdint>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "GridMask.hpp"

namespace dynamap::planning {

namespace {

// Unknown cells under the mask take `state`; returns how many.
int FillUnknown(GridMap& map, const cv::Mat& mask, CellState state) {
  int filled = 0;
  for (int y = 0; y < map.height; ++y) {
    const auto* row = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < map.width; ++x) {
      CellState& cell = map.cells[static_cast<std::size_t>(y) * map.width + x];
      if (row[x] != 0 && cell == CellState::kUnknown) {
        cell = state;
        ++filled;
      }
    }
  }
  return filled;
}

// Morphological closing of the cells in `state`; unknown cells it covers take that state.
int CloseUnknownGaps(GridMap& map, CellState state, double max_gap_m, bool thin) {
  if (map.width == 0 || map.height == 0 || max_gap_m <= 0.0) return 0;
  // Odd kernel size covering the gap: a gap of n cells needs a disc n + 1 cells across.
  const int gap_cells = static_cast<int>(std::floor(max_gap_m / map.resolution_m));
  if (gap_cells < 1) return 0;
  const int size = 2 * ((gap_cells + 2) / 2) + 1;
  const cv::Mat mask = MaskOf(map, state);
  cv::Mat closed;
  // Outside the grid counts as not in `state`, so the closing never pulls cells in from
  // beyond the border.
  const auto close = [&](const cv::Mat& kernel) {
    cv::Mat out;
    cv::morphologyEx(mask, out, cv::MORPH_CLOSE, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT,
                     cv::Scalar(0));
    return out;
  };
  if (!thin) {
    closed = close(cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size)));
  } else {
    // Walls are lines one or two cells thick: a disc cannot bridge a gap in them, a line
    // along the wall can. Four directions cover walls at any angle within 22.5°.
    cv::Mat horizontal = cv::Mat::ones(1, size, CV_8UC1);
    cv::Mat vertical = cv::Mat::ones(size, 1, CV_8UC1);
    cv::Mat diagonal = cv::Mat::eye(size, size, CV_8UC1);
    cv::Mat anti;
    cv::flip(diagonal, anti, 1);
    closed = close(horizontal) | close(vertical) | close(diagonal) | close(anti);
  }
  return FillUnknown(map, closed, state);
}

}  // namespace

int CloseFloorGaps(GridMap& map, double max_gap_m) {
  return CloseUnknownGaps(map, CellState::kNavigable, max_gap_m, false);
}

int CloseWallGaps(GridMap& map, double max_gap_m) {
  return CloseUnknownGaps(map, CellState::kObstacle, max_gap_m, true);
}

int AssumeFloorAround(GridMap& map, double x_m, double y_m, double radius_m) {
  const GridIndex centre = map.CellAt(x_m, y_m);
  if (!map.Contains(centre) || radius_m <= 0.0) return 0;
  const double r2 = (radius_m / map.resolution_m) * (radius_m / map.resolution_m);
  std::vector<std::uint8_t> visited(map.cells.size(), 0);
  std::vector<GridIndex> stack{centre};
  visited[map.Index(centre)] = 1;
  int filled = 0;
  while (!stack.empty()) {
    const GridIndex c = stack.back();
    stack.pop_back();
    CellState& cell = map.cells[map.Index(c)];
    if (cell == CellState::kObstacle || cell == CellState::kHole) continue;
    if (cell == CellState::kUnknown) {
      cell = CellState::kNavigable;
      ++filled;
    }
    const GridIndex next[4] = {{c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}};
    for (const GridIndex& n : next) {
      const double dx = n.x - centre.x;
      const double dy = n.y - centre.y;
      if (!map.Contains(n) || dx * dx + dy * dy > r2 || visited[map.Index(n)] != 0) continue;
      visited[map.Index(n)] = 1;
      stack.push_back(n);
    }
  }
  return filled;
}

int ExtendHolesIntoUnknown(GridMap& map, double radius_m) {
  const int r = static_cast<int>(std::floor(radius_m / map.resolution_m));
  if (r <= 0 || map.width == 0 || map.height == 0) return 0;
  cv::Mat grown;
  cv::dilate(MaskOf(map, CellState::kHole), grown,
             cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1)),
             cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  return FillUnknown(map, grown, CellState::kHole);
}

}  // namespace dynamap::planning
