#include "dynamap/planning/FloorGaps.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace dynamap::planning {

int CloseFloorGaps(GridMap& map, double max_gap_m) {
  if (map.width == 0 || map.height == 0 || max_gap_m <= 0.0) return 0;
  // Odd kernel size covering the gap: a gap of n cells needs a disc n + 1 cells across.
  const int gap_cells = static_cast<int>(std::floor(max_gap_m / map.resolution_m));
  if (gap_cells < 1) return 0;
  const int size = 2 * ((gap_cells + 2) / 2) + 1;
  cv::Mat navigable(map.height, map.width, CV_8UC1);
  for (int y = 0; y < map.height; ++y) {
    auto* row = navigable.ptr<std::uint8_t>(y);
    for (int x = 0; x < map.width; ++x) {
      row[x] = map.cells[static_cast<std::size_t>(y) * map.width + x] == CellState::kNavigable
                   ? 255
                   : 0;
    }
  }
  cv::Mat closed;
  // Outside the grid counts as not navigable, so the closing never pulls floor in from
  // beyond the border.
  cv::morphologyEx(navigable, closed, cv::MORPH_CLOSE,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size)),
                   cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(0));
  int filled = 0;
  for (int y = 0; y < map.height; ++y) {
    const auto* row = closed.ptr<std::uint8_t>(y);
    for (int x = 0; x < map.width; ++x) {
      CellState& cell = map.cells[static_cast<std::size_t>(y) * map.width + x];
      if (row[x] != 0 && cell == CellState::kUnknown) {
        cell = CellState::kNavigable;
        ++filled;
      }
    }
  }
  return filled;
}

}  // namespace dynamap::planning
