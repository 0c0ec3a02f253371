// The estimated rig drawn on the robot (Calibration workspace, after solving): the base
// (footprint disc and axes), each Kinect's body and view frustum at its estimated pose,
// coloured by whether all its parameters are calibrated (green), some weak (orange) or
// not observable (red); its uncertainty as a translucent ellipsoid (3σ of x, y, z) and a
// cone about the optical axis (3σ of pitch and yaw), both magnified so millimetres and
// tenths of a degree can be seen; the guessed pose as a grey frustum and, in the
// simulator, the true pose as a blue one.
#pragma once

#include <QVTKOpenGLNativeWidget.h>
#include <vtkSmartPointer.h>

#include <vector>

#include "dynamap/calibration/RigSolver.hpp"
#include "dynamap/robotio/Rig.hpp"

class vtkRenderer;

namespace dynamap::app::gui {

class RigView : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  // Uncertainty glyphs are drawn this many times their size.
  static constexpr double kUncertaintyMagnification = 20.0;

  explicit RigView(QWidget* parent = nullptr);
  ~RigView() override;

  // `truth` is empty unless known (simulator).
  void ShowRig(const calibration::SolverResult& result, const robotio::Rig& guess,
               const robotio::Rig& truth, double robot_radius_m);
  void Clear();

  // What is drawn, for tests: one estimated pose per Kinect (T_base_kinect) and the
  // uncertainty ellipsoids' semi-axes before magnification (m).
  [[nodiscard]] const std::vector<Eigen::Isometry3d>& DrawnPoses() const { return poses_; }
  [[nodiscard]] const std::vector<Eigen::Vector3d>& DrawnSemiAxes() const { return semi_axes_; }

 private:
  vtkSmartPointer<vtkRenderer> renderer_;
  std::vector<Eigen::Isometry3d> poses_;
  std::vector<Eigen::Vector3d> semi_axes_;
};

}  // namespace dynamap::app::gui
