// Residual plots of a calibration, one PNG per capture step (floor, turn, straight, arcs):
// how well each Kinect's floor fits and ICP motions agree with the calibrated rig, before
// and after refinement, so an operator can see outliers and unmodelled effects.
#pragma once

#include <string>
#include <vector>

#include "dynamap/calibration/CaptureData.hpp"
#include "dynamap/calibration/RigSolver.hpp"
#include "dynamap/robotio/Expected.hpp"

namespace dynamap::calibration {

// Writes residuals_floor.png, residuals_turn.png, residuals_straight.png and
// residuals_arcs.png into `dir` (atomically); returns the paths written.
[[nodiscard]] robotio::Expected<std::vector<std::string>> WriteResidualPlots(
    const SolverResult& result, const CaptureData& capture, const std::string& dir);

}  // namespace dynamap::calibration
