// After solving: the estimated rig as a table (per Kinect roll, pitch, yaw, x, y, z,
// latency, and the two wheel scales) with standard deviations, observability verdicts and,
// against the simulator, the error to the true rig; the solver's warnings; and the residual
// plots of each capture step.
#pragma once

#include <QWidget>
#include <string>
#include <vector>

#include "dynamap/calibration/RigSolver.hpp"
#include "dynamap/robotio/Rig.hpp"

class QLabel;
class QTabWidget;
class QTableWidget;

namespace dynamap::app::gui {

class CalibrationResults : public QWidget {
  Q_OBJECT

 public:
  explicit CalibrationResults(QWidget* parent = nullptr);

  // `truth` has one mount per Kinect when known (simulator), else is empty.
  void Show(const calibration::SolverResult& result, const robotio::Rig& truth,
            double true_scale_left, double true_scale_right);
  void ShowPlots(const std::vector<std::string>& files);
  void Clear();

  [[nodiscard]] QTableWidget* Table() const { return table_; }
  [[nodiscard]] int PlotCount() const;

 private:
  QLabel* summary_ = nullptr;
  QTableWidget* table_ = nullptr;
  QTabWidget* plots_ = nullptr;
};

}  // namespace dynamap::app::gui
