// A picture of how far estimated paths are from the ground truth over time: one line per
// estimate (SLAM, SLAM before loop closure, odometry alone), position error in metres
// against seconds since the first ground-truth pose, with each line's ATE in its legend.
#pragma once

#include <string>
#include <vector>

#include "dynamap/mapping/TrajectoryEvaluation.hpp"
#include "dynamap/robotio/Expected.hpp"
#include "dynamap/robotio/TumTrajectory.hpp"

namespace dynamap::mapping {

struct PlottedTrajectory {
  std::string label;
  robotio::Trajectory poses;
};

// Position error of each pose of `estimate` that associates with a ground-truth pose
// (TUM association, no alignment): pairs of (seconds since the first ground-truth stamp,
// metres), in ground-truth order.
[[nodiscard]] std::vector<std::pair<double, double>> PositionErrorOverTime(
    const robotio::Trajectory& ground_truth, const robotio::Trajectory& estimate,
    double max_stamp_difference_s = 0.02);

// Writes the plot as a PNG (atomically). Errors name the file; empty estimates are left
// out of the plot, and with nothing to draw it is an error.
[[nodiscard]] robotio::Status WriteTrajectoryErrorPlot(const std::string& file,
                                                       const robotio::Trajectory& ground_truth,
                                                       const std::vector<PlottedTrajectory>& estimates);

}  // namespace dynamap::mapping
