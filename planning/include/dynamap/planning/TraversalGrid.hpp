// What the path planners search: per cell a blocked flag and a proximity penalty, and the
// 8-connected move costs over it (diagonal √2, no corner cutting; thesis 6.3). Moving AI
// maps and projected maps both become this grid.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "dynamap/planning/GridMap.hpp"

namespace dynamap::planning {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Move costs are multiples of 2^-20 so that every sum, key and comparison in the searches
// is exact: with rounded floating-point costs D* Lite's ties between a repaired and a stale
// g-value can break the wrong way and return a worse path than A*. The quantisation error
// (< 4e-7 relative per move) is far below the benchmark's 1e-3 tolerance.
inline constexpr double kCostQuantum = 1.0 / 1048576.0;
[[nodiscard]] inline double QuantizeCost(double cost) {
  return std::round(cost / kCostQuantum) * kCostQuantum;
}
// √2 rounded to the cost quantum (1482910 / 2^20).
inline constexpr double kSqrt2 = 1482910.0 / 1048576.0;

// The 8 moves: 4 straight first, then 4 diagonal.
struct Move {
  int dx;
  int dy;
  double length;  // cells.
};
inline constexpr std::array<Move, 8> kMoves = {{{1, 0, 1.0},
                                                {-1, 0, 1.0},
                                                {0, 1, 1.0},
                                                {0, -1, 1.0},
                                                {1, 1, kSqrt2},
                                                {1, -1, kSqrt2},
                                                {-1, 1, kSqrt2},
                                                {-1, -1, kSqrt2}}};

struct TraversalGrid {
  int width = 0;
  int height = 0;
  // Per cell: kInfinity = blocked, otherwise a penalty >= 0 added (relative) to the cost of
  // moves touching the cell. A move a→b of length L costs L·(1 + (p_a + p_b)/2), which is
  // symmetric, so a backward search (D* Lite) and a forward one (A*) agree.
  std::vector<double> penalty;

  TraversalGrid() = default;
  TraversalGrid(int w, int h, double fill = 0.0)
      : width(w), height(h),
        penalty(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), fill) {}

  [[nodiscard]] bool Contains(GridIndex c) const {
    return c.x >= 0 && c.y >= 0 && c.x < width && c.y < height;
  }
  [[nodiscard]] int Index(GridIndex c) const { return c.y * width + c.x; }
  [[nodiscard]] GridIndex Cell(int index) const { return {index % width, index / width}; }
  [[nodiscard]] bool Blocked(GridIndex c) const { return !Contains(c) || Blocked(Index(c)); }
  [[nodiscard]] bool Blocked(int index) const { return penalty[index] == kInfinity; }

  // Cost of the move from `a` by `m`; kInfinity when either end is blocked or when a
  // diagonal would cut the corner of a blocked cell.
  [[nodiscard]] double MoveCost(GridIndex a, const Move& m) const {
    const GridIndex b{a.x + m.dx, a.y + m.dy};
    if (Blocked(a) || Blocked(b)) return kInfinity;
    if (m.dx != 0 && m.dy != 0 &&
        (Blocked(GridIndex{a.x + m.dx, a.y}) || Blocked(GridIndex{a.x, a.y + m.dy}))) {
      return kInfinity;
    }
    const double extra = penalty[Index(a)] + penalty[Index(b)];
    return extra == 0.0 ? m.length : QuantizeCost(m.length * (1.0 + 0.5 * extra));
  }
};

// The robot stands where it stands: a blocked cell under it (inflation around a wall it
// came close to, an obstacle drawn over it) must not wall it in. The cell becomes passable
// with a high penalty, so paths still leave it by the shortest way. Off the grid: nothing.
inline constexpr double kStandingCellPenalty = 10.0;
inline void FreeStandingCell(TraversalGrid& grid, GridIndex robot) {
  if (grid.Contains(robot) && grid.Blocked(robot)) {
    grid.penalty[grid.Index(robot)] = kStandingCellPenalty;
  }
}

// Octile distance: the exact cost on an empty grid without penalties, so an admissible and
// consistent heuristic for every TraversalGrid (penalties are >= 0).
[[nodiscard]] inline double OctileDistance(GridIndex a, GridIndex b) {
  const int dx = std::abs(a.x - b.x);
  const int dy = std::abs(a.y - b.y);
  return (dx + dy) + (kSqrt2 - 2.0) * (dx < dy ? dx : dy);
}

// A path through cell centres and its cost in cells (multiply by the resolution for m).
struct GridPath {
  bool found = false;
  double cost = kInfinity;        // Sum of MoveCost along `cells`.
  std::vector<GridIndex> cells;   // start ... goal, empty when not found.
  long expansions = 0;            // Nodes expanded to get it (for benchmarks).
};

// Sum of MoveCost along consecutive cells (kInfinity if two are not neighbours or blocked).
[[nodiscard]] double PathCost(const TraversalGrid& grid, const std::vector<GridIndex>& cells);

}  // namespace dynamap::planning
