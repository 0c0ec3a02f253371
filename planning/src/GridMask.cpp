#include "GridMask.hpp"

#include <cstdint>

namespace dynamap::planning {

cv::Mat MaskOf(const GridMap& map, CellState state) {
  cv::Mat mask(map.height, map.width, CV_8UC1);
  for (int y = 0; y < map.height; ++y) {
    auto* row = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < map.width; ++x) {
      row[x] = map.cells[static_cast<std::size_t>(y) * map.width + x] == state ? 255 : 0;
    }
  }
  return mask;
}

}  // namespace dynamap::planning
