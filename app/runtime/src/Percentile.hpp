// The q-quantile (0..1, nearest rank below) of timing samples for the mission report.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace dynamap::app::runtime {

[[nodiscard]] inline double Percentile(std::vector<double> values, double q) {
  if (values.empty()) return 0.0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(values.size() - 1));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

}  // namespace dynamap::app::runtime
