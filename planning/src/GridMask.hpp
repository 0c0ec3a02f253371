// A grid's cells of one state as an OpenCV mask (255 where the cell is in `state`, else
// 0; row y of the mask is grid row y), for the image-processing steps of planning.
#pragma once

#include <opencv2/core.hpp>

#include "dynamap/planning/GridMap.hpp"

namespace dynamap::planning {

[[nodiscard]] cv::Mat MaskOf(const GridMap& map, CellState state);

}  // namespace dynamap::planning
