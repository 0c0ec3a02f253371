#include "dynamap/planning/GridMap.hpp"

#include <cmath>

namespace dynamap::planning {

GridIndex GridMap::CellAt(double x_m, double y_m) const {
  return {static_cast<int>(std::floor((x_m - origin_x_m) / resolution_m)),
          static_cast<int>(std::floor((y_m - origin_y_m) / resolution_m))};
}

}  // namespace dynamap::planning
