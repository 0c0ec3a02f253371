// The projected 2D map the planners work on: one state per cell (navigable, obstacle,
// hole, unknown) at the 3D map's resolution, placed in the map frame (thesis 6.1).
#pragma once

#include <cstdint>
#include <vector>

namespace dynamap::planning {

enum class CellState : std::uint8_t {
  kUnknown = 0,    // Never observed well enough to decide.
  kNavigable = 1,  // Floor seen, nothing in the robot's height band.
  kObstacle = 2,   // Something between step height and robot height.
  kHole = 3,       // Floor missing or free space below floor level (descending stairs).
};

// Integer cell coordinates; x is the column, y the row.
struct GridIndex {
  int x = 0;
  int y = 0;
  friend bool operator==(const GridIndex& a, const GridIndex& b) {
    return a.x == b.x && a.y == b.y;
  }
  friend bool operator!=(const GridIndex& a, const GridIndex& b) { return !(a == b); }
};

struct GridMap {
  int width = 0;              // cells along map x.
  int height = 0;             // cells along map y.
  double resolution_m = 0.05; // m per cell edge.
  double origin_x_m = 0.0;    // m, map frame x of the lower corner of cell (0, 0).
  double origin_y_m = 0.0;    // m, map frame y of the lower corner of cell (0, 0).
  std::vector<CellState> cells;  // Row-major: index = y * width + x.

  GridMap() = default;
  GridMap(int w, int h, double resolution, CellState fill = CellState::kUnknown)
      : width(w), height(h), resolution_m(resolution),
        cells(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}

  [[nodiscard]] bool Contains(GridIndex c) const {
    return c.x >= 0 && c.y >= 0 && c.x < width && c.y < height;
  }
  [[nodiscard]] int Index(GridIndex c) const { return c.y * width + c.x; }
  [[nodiscard]] GridIndex Cell(int index) const { return {index % width, index / width}; }
  [[nodiscard]] CellState At(GridIndex c) const { return cells[Index(c)]; }
  void Set(GridIndex c, CellState s) { cells[Index(c)] = s; }

  // Cell containing the map-frame point (may lie outside the grid; check Contains).
  [[nodiscard]] GridIndex CellAt(double x_m, double y_m) const;
  // Map-frame centre of a cell, m.
  [[nodiscard]] double CenterX(int x) const { return origin_x_m + (x + 0.5) * resolution_m; }
  [[nodiscard]] double CenterY(int y) const { return origin_y_m + (y + 0.5) * resolution_m; }
};

}  // namespace dynamap::planning
