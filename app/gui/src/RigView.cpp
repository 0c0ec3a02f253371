#include "dynamap/app/gui/RigView.hpp"

#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkBillboardTextActor3D.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMatrix4x4.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace dynamap::app::gui {

namespace cal = calibration;

namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr double kFrustumDepthM = 0.3;  // m, how far the drawn view frustums reach.
constexpr double kHalfFovX = 28.5 * kDeg;  // Kinect v1: 57° × 43°.
constexpr double kHalfFovY = 21.5 * kDeg;

using Rgb = std::array<double, 3>;
constexpr Rgb kCalibrated = {0.30, 0.85, 0.35};
constexpr Rgb kWeak = {1.00, 0.65, 0.10};
constexpr Rgb kNotObservable = {0.95, 0.25, 0.20};
constexpr Rgb kGuess = {0.65, 0.65, 0.65};
constexpr Rgb kTruth = {0.30, 0.55, 1.00};

vtkSmartPointer<vtkTransform> ToVtk(const Eigen::Isometry3d& pose) {
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  for (int r = 0; r < 4; ++r) {
    for (int c = 0; c < 4; ++c) matrix->SetElement(r, c, pose.matrix()(r, c));
  }
  auto transform = vtkSmartPointer<vtkTransform>::New();
  transform->SetMatrix(matrix);
  return transform;
}

vtkSmartPointer<vtkActor> ColouredActor(vtkPolyDataMapper* mapper, const Rgb& rgb) {
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(rgb[0], rgb[1], rgb[2]);
  return actor;
}

vtkSmartPointer<vtkActor> Actor(vtkAlgorithmOutput* port, const Rgb& rgb, double opacity) {
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputConnection(port);
  auto actor = ColouredActor(mapper, rgb);
  actor->GetProperty()->SetOpacity(opacity);
  return actor;
}

// The view frustum of a camera at T_base_kinect (optical frame), as lines.
vtkSmartPointer<vtkActor> Frustum(const Eigen::Isometry3d& T_base_kinect, const Rgb& rgb,
                                  double line_width) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  const Eigen::Vector3d apex = T_base_kinect.translation();
  points->InsertNextPoint(apex.x(), apex.y(), apex.z());
  const double x = std::tan(kHalfFovX) * kFrustumDepthM;
  const double y = std::tan(kHalfFovY) * kFrustumDepthM;
  for (const auto& corner : {Eigen::Vector3d(-x, -y, kFrustumDepthM), Eigen::Vector3d(x, -y, kFrustumDepthM),
                             Eigen::Vector3d(x, y, kFrustumDepthM), Eigen::Vector3d(-x, y, kFrustumDepthM)}) {
    const Eigen::Vector3d p = T_base_kinect * corner;
    points->InsertNextPoint(p.x(), p.y(), p.z());
  }
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  for (vtkIdType i = 1; i <= 4; ++i) {
    const vtkIdType ray[2] = {0, i};
    lines->InsertNextCell(2, ray);
    const vtkIdType edge[2] = {i, i % 4 + 1};
    lines->InsertNextCell(2, edge);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  mapper->SetInputData(data);
  auto actor = ColouredActor(mapper, rgb);
  actor->GetProperty()->SetLineWidth(static_cast<float>(line_width));
  return actor;
}

// The Kinect's bar at T_base_kinect: 28 cm along the optical x axis (image right), 4 cm
// along y (image down), 6 cm along z (the viewing direction).
vtkSmartPointer<vtkActor> KinectBody(const Eigen::Isometry3d& T_base_kinect, const Rgb& rgb) {
  auto box = vtkSmartPointer<vtkCubeSource>::New();
  box->SetXLength(0.28);
  box->SetYLength(0.04);
  box->SetZLength(0.06);
  auto placed = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  placed->SetInputConnection(box->GetOutputPort());
  placed->SetTransform(ToVtk(T_base_kinect));
  auto actor = Actor(placed->GetOutputPort(), rgb, 1.0);
  actor->GetProperty()->SetAmbient(0.3);
  return actor;
}

Rgb StatusColour(const cal::KinectEstimate& kinect) {
  bool weak = false;
  for (const cal::ParameterEstimate& p : kinect.parameters) {
    if (p.status == cal::Observability::kNotObservable) return kNotObservable;
    if (p.status == cal::Observability::kWeak) weak = true;
  }
  return weak ? kWeak : kCalibrated;
}

std::string LabelText(const cal::KinectEstimate& kinect) {
  std::string text = kinect.id;
  std::string weak;
  for (const cal::ParameterEstimate& p : kinect.parameters) {
    if (p.status == cal::Observability::kCalibrated) continue;
    const std::string field = p.name.substr(p.name.find('.') + 1);
    weak += (weak.empty() ? "" : ", ") + field;
  }
  char line[160];
  const auto& q = kinect.parameters;
  if (q.size() >= 7) {
    std::snprintf(line, sizeof line, "\nyaw %.2f° ± %.2f°, pitch %.2f° ± %.2f°\nxyz ± %.1f %.1f %.1f mm",
                  q[2].estimate / kDeg, q[2].std_dev / kDeg, q[1].estimate / kDeg,
                  q[1].std_dev / kDeg, q[3].std_dev * 1e3, q[4].std_dev * 1e3, q[5].std_dev * 1e3);
    text += line;
  }
  if (!weak.empty()) text += "\nnot calibrated: " + weak;
  return text;
}

}  // namespace

RigView::RigView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  setRenderWindow(window);
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderer_->GradientBackgroundOn();
  renderer_->SetBackground(0.10, 0.11, 0.13);
  renderer_->SetBackground2(0.27, 0.30, 0.35);
  window->AddRenderer(renderer_);
  setMinimumSize(200, 150);
}

RigView::~RigView() = default;

void RigView::Clear() {
  renderer_->RemoveAllViewProps();
  poses_.clear();
  semi_axes_.clear();
  renderWindow()->Render();
}

void RigView::ShowRig(const cal::SolverResult& result, const robotio::Rig& guess,
                      const robotio::Rig& truth, double robot_radius_m) {
  Clear();
  // The base: a translucent disc of the footprint up to the lower Kinect, and its axes.
  auto disc = vtkSmartPointer<vtkCylinderSource>::New();
  disc->SetRadius(robot_radius_m);
  disc->SetHeight(0.3);
  disc->SetCenter(0.0, 0.15, 0.0);
  disc->SetResolution(48);
  auto upright = vtkSmartPointer<vtkTransform>::New();
  upright->RotateX(90.0);  // The cylinder source's axis is y.
  auto placed_disc = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  placed_disc->SetInputConnection(disc->GetOutputPort());
  placed_disc->SetTransform(upright);
  renderer_->AddActor(Actor(placed_disc->GetOutputPort(), {0.85, 0.72, 0.25}, 0.35));
  auto axes = vtkSmartPointer<vtkAxesActor>::New();
  axes->SetTotalLength(0.3, 0.3, 0.3);
  axes->SetShaftTypeToCylinder();
  axes->SetCylinderRadius(0.02);
  axes->AxisLabelsOff();
  renderer_->AddActor(axes);

  const robotio::Rig estimated = result.ToRig(guess);
  for (std::size_t k = 0; k < result.kinects.size() && k < estimated.kinects.size(); ++k) {
    const cal::KinectEstimate& kinect = result.kinects[k];
    const Eigen::Isometry3d pose = estimated.kinects[k].T_base_kinect;
    const Rgb colour = StatusColour(kinect);
    poses_.push_back(pose);
    if (k < guess.kinects.size()) renderer_->AddActor(Frustum(guess.kinects[k].T_base_kinect, kGuess, 1.0));
    if (k < truth.kinects.size()) renderer_->AddActor(Frustum(truth.kinects[k].T_base_kinect, kTruth, 1.5));
    renderer_->AddActor(Frustum(pose, colour, 2.5));
    renderer_->AddActor(KinectBody(pose, colour));

    // Position uncertainty: 3σ of x, y, z in base, magnified.
    const auto& q = kinect.parameters;
    const Eigen::Vector3d semi(3.0 * q[3].std_dev, 3.0 * q[4].std_dev, 3.0 * q[5].std_dev);
    semi_axes_.push_back(semi);
    auto sphere = vtkSmartPointer<vtkSphereSource>::New();
    sphere->SetRadius(1.0);
    sphere->SetThetaResolution(24);
    sphere->SetPhiResolution(16);
    auto scale = vtkSmartPointer<vtkTransform>::New();
    const Eigen::Vector3d c = pose.translation();
    scale->Translate(c.x(), c.y(), c.z());
    const double m = kUncertaintyMagnification;
    scale->Scale(std::max(semi.x() * m, 1e-3), std::max(semi.y() * m, 1e-3),
                 std::max(semi.z() * m, 1e-3));
    auto ellipsoid = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
    ellipsoid->SetInputConnection(sphere->GetOutputPort());
    ellipsoid->SetTransform(scale);
    renderer_->AddActor(Actor(ellipsoid->GetOutputPort(), colour, 0.35));

    // Pointing uncertainty: a cone about the optical axis, 3σ of the larger of pitch and
    // yaw, magnified.
    const double half_angle =
        std::min(80.0 * kDeg, 3.0 * std::max(q[1].std_dev, q[2].std_dev) * m);
    auto cone = vtkSmartPointer<vtkConeSource>::New();
    cone->SetResolution(32);
    cone->SetHeight(kFrustumDepthM);
    cone->SetRadius(kFrustumDepthM * std::tan(half_angle));
    cone->SetDirection(-1.0, 0.0, 0.0);  // Tip at the camera, opening along +x ...
    cone->SetCenter(kFrustumDepthM / 2.0, 0.0, 0.0);
    cone->CappingOff();
    auto along_optical = vtkSmartPointer<vtkTransform>::New();
    along_optical->SetMatrix(ToVtk(pose)->GetMatrix());
    along_optical->RotateY(-90.0);  // ... which becomes the optical z axis.
    auto placed_cone = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
    placed_cone->SetInputConnection(cone->GetOutputPort());
    placed_cone->SetTransform(along_optical);
    renderer_->AddActor(Actor(placed_cone->GetOutputPort(), colour, 0.25));

    auto label = vtkSmartPointer<vtkBillboardTextActor3D>::New();
    label->SetInput(LabelText(kinect).c_str());
    // Beside the camera, on the side away from the base's centre.
    const Eigen::Vector3d c_xy(c.x(), c.y(), 0.0);
    const Eigen::Vector3d outward = c_xy.norm() > 1e-6 ? Eigen::Vector3d(c_xy.normalized()) : Eigen::Vector3d::UnitX();
    const Eigen::Vector3d at = c + 0.35 * outward + Eigen::Vector3d(0.0, 0.0, 0.12 * (k == 0 ? 1.0 : -1.0));
    label->SetPosition(at.x(), at.y(), at.z());
    label->GetTextProperty()->SetFontSize(12);
    label->GetTextProperty()->SetColor(colour[0], colour[1], colour[2]);
    label->GetTextProperty()->SetBackgroundColor(0.0, 0.0, 0.0);
    label->GetTextProperty()->SetBackgroundOpacity(0.55);
    renderer_->AddActor(label);
  }

  auto legend = vtkSmartPointer<vtkTextActor>::New();
  char text[200];
  std::snprintf(text, sizeof text,
                "estimated: green calibrated, orange weak, red not observable\n"
                "grey: guess%s   ellipsoids and cones: 3σ × %.0f",
                truth.kinects.empty() ? "" : ", blue: truth", kUncertaintyMagnification);
  legend->SetInput(text);
  legend->SetDisplayPosition(10, 10);
  legend->GetTextProperty()->SetFontSize(13);
  legend->GetTextProperty()->SetColor(0.9, 0.9, 0.9);
  renderer_->AddActor2D(legend);

  // From front left, above: the base, both Kinects and their labels in view.
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetFocalPoint(0.15, 0.0, 0.4);
  camera->SetPosition(1.55, 0.95, 1.15);
  camera->SetViewUp(0.0, 0.0, 1.0);
  renderer_->ResetCameraClippingRange();
  renderWindow()->Render();
}

}  // namespace dynamap::app::gui
