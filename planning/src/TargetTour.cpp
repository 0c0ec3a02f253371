#include "dynamap/planning/TargetTour.hpp"

#include <algorithm>
#include <cmath>

#include "dynamap/planning/CostToGo.hpp"

namespace dynamap::planning {

namespace {

constexpr int kMaxTwoOptPasses = 50;

}  // namespace

double TourLength(const std::vector<int>& order, const TourCosts& costs) {
  if (order.empty()) return 0.0;
  double length = costs.from_robot[order.front()];
  for (std::size_t k = 1; k < order.size(); ++k) length += costs.between[order[k - 1]][order[k]];
  return length + costs.to_end[order.back()];
}

std::vector<int> TourFrom(int first, const TourCosts& costs) {
  const int n = static_cast<int>(costs.from_robot.size());
  std::vector<int> order{first};
  std::vector<bool> visited(static_cast<std::size_t>(n), false);
  visited[first] = true;
  for (int k = 1; k < n; ++k) {
    const int last = order.back();
    int next = -1;
    for (int j = 0; j < n; ++j) {
      if (!visited[j] && (next < 0 || costs.between[last][j] < costs.between[last][next])) next = j;
    }
    visited[next] = true;
    order.push_back(next);
  }
  // 2-opt: reverse order[i..j] (i >= 1, the first stop stays) while that shortens the tour.
  // The stop after order.back() is the end, reached by to_end.
  const auto after = [&](int j) {
    return j + 1 < n ? costs.between[order[j]][order[j + 1]] : costs.to_end[order[j]];
  };
  const auto after_reversed = [&](int i, int j) {  // order[i] followed by order[j + 1].
    return j + 1 < n ? costs.between[order[i]][order[j + 1]] : costs.to_end[order[i]];
  };
  for (int pass = 0; pass < kMaxTwoOptPasses; ++pass) {
    bool improved = false;
    for (int i = 1; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        const double before = costs.between[order[i - 1]][order[i]] + after(j);
        const double reversed = costs.between[order[i - 1]][order[j]] + after_reversed(i, j);
        if (reversed < before - 1e-9) {
          std::reverse(order.begin() + i, order.begin() + j + 1);
          improved = true;
        }
      }
    }
    if (!improved) break;
  }
  return order;
}

std::vector<double> TourLengthsByFirstStop(const TourCosts& costs) {
  std::vector<double> lengths;
  for (int first = 0; first < static_cast<int>(costs.from_robot.size()); ++first) {
    lengths.push_back(TourLength(TourFrom(first, costs), costs));
  }
  return lengths;
}

std::vector<std::vector<double>> CoarseDistances(const TraversalGrid& grid,
                                                 const std::vector<GridIndex>& from,
                                                 const std::vector<GridIndex>& to, int factor,
                                                 double resolution_m) {
  factor = std::max(1, factor);
  TraversalGrid coarse((grid.width + factor - 1) / factor, (grid.height + factor - 1) / factor,
                       kInfinity);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      if (!grid.Blocked(grid.Index({x, y}))) coarse.penalty[coarse.Index({x / factor, y / factor})] = 0.0;
    }
  }
  const auto coarse_cell = [&](GridIndex c) { return GridIndex{c.x / factor, c.y / factor}; };
  const double cell_m = factor * resolution_m;
  std::vector<std::vector<double>> distances;
  for (const GridIndex& a : from) {
    const std::vector<double> cost = CostToGo(coarse, coarse_cell(a));
    std::vector<double> row;
    for (const GridIndex& b : to) {
      const GridIndex cb = coarse_cell(b);
      const double c = coarse.Contains(cb) ? cost[coarse.Index(cb)] : kInfinity;
      row.push_back(c < kInfinity ? c * cell_m
                                  : 3.0 * std::hypot(a.x - b.x, a.y - b.y) * resolution_m);
    }
    distances.push_back(std::move(row));
  }
  return distances;
}

}  // namespace dynamap::planning
