// `dynamap calibrate`: the guided Kinect rig calibration (calibration::CalibrationSession)
// from a recording (--log DIR) or driven in the simulator (--world FILE, whose true rig is
// the guess perturbed per --seed). Writes the rig file, report.json and residual plots.
#pragma once

#include <CLI/CLI.hpp>

namespace dynamap::app {

void RegisterCalibrateCommand(CLI::App& app);

}  // namespace dynamap::app
