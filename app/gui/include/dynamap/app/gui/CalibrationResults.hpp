// After solving: the estimated rig as a table (per Kinect roll, pitch, yaw, x, y, z,
// latency, and the two wheel scales) with standard deviations, observability verdicts and,
// against the simulator, the error to the true rig; the solver's warnings; the rig drawn
// on the robot in 3D with its uncertainties (RigView); and the residual plots of each
// capture step.
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

class RigView;

class CalibrationResults : public QWidget {
  Q_OBJECT

 public:
  explicit CalibrationResults(QWidget* parent = nullptr);

  // `truth` has one mount per Kinect when known (simulator), else is empty.
  void Show(const calibration::SolverResult& result, const robotio::Rig& guess,
            const robotio::Rig& truth, double true_scale_left, double true_scale_right,
            double robot_radius_m);
  void ShowPlots(const std::vector<std::string>& files);
  void Clear();

  [[nodiscard]] QTableWidget* Table() const { return table_; }
  [[nodiscard]] int PlotCount() const;
  [[nodiscard]] RigView* Rig3d() const { return rig_view_; }
  // Brings the 3D rig tab to the front.
  void ShowRigTab();

 private:
  QLabel* summary_ = nullptr;
  QTableWidget* table_ = nullptr;
  QTabWidget* plots_ = nullptr;
  QTabWidget* tabs_ = nullptr;
  RigView* rig_view_ = nullptr;
};

}  // namespace dynamap::app::gui
