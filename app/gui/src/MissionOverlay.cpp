#include "dynamap/app/gui/MissionOverlay.hpp"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCellArray.h>
#include <vtkConeSource.h>
#include <vtkCylinderSource.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>

#include <cmath>

namespace dynamap::app::gui {

namespace {

constexpr double kLineZ = 0.04;  // m, trail and path float just above the floor voxels.

vtkSmartPointer<vtkActor> MakeActor(vtkSmartPointer<vtkPolyDataMapper> mapper,
                                    double r, double g, double b) {
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->PickableOff();
  return actor;
}

template <typename Points, typename XY>
void FillPolyline(vtkPolyData* data, const Points& points, XY xy) {
  auto vtk_points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  if (points.size() > 1) {
    lines->InsertNextCell(static_cast<vtkIdType>(points.size()));
    for (const auto& p : points) {
      const Eigen::Vector2d q = xy(p);
      lines->InsertCellPoint(vtk_points->InsertNextPoint(q.x(), q.y(), kLineZ));
    }
  }
  data->SetPoints(vtk_points);
  data->SetLines(lines);
  data->Modified();
}

}  // namespace

MissionOverlay::MissionOverlay(vtkRenderer* renderer, double robot_radius_m)
    : renderer_(renderer) {
  // The robot in its own frame: a flat disc (x forward) and an arrow along +x; the actor's
  // pose places it.
  auto body = vtkSmartPointer<vtkCylinderSource>::New();
  body->SetRadius(robot_radius_m);
  body->SetHeight(0.25);
  body->SetResolution(32);
  auto body_pose = vtkSmartPointer<vtkTransform>::New();
  body_pose->Translate(0.0, 0.0, 0.2);
  body_pose->RotateX(90.0);  // The cylinder source's axis is y.
  auto arrow = vtkSmartPointer<vtkConeSource>::New();
  arrow->SetCenter(robot_radius_m + 0.1, 0.0, 0.2);
  arrow->SetDirection(1.0, 0.0, 0.0);
  arrow->SetHeight(0.35);
  arrow->SetRadius(0.12);
  arrow->SetResolution(16);
  auto placed_body = vtkSmartPointer<vtkTransformPolyDataFilter>::New();
  placed_body->SetInputConnection(body->GetOutputPort());
  placed_body->SetTransform(body_pose);
  auto append = vtkSmartPointer<vtkAppendPolyData>::New();
  append->AddInputConnection(placed_body->GetOutputPort());
  append->AddInputConnection(arrow->GetOutputPort());
  auto robot_mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  robot_mapper->SetInputConnection(append->GetOutputPort());
  robot_ = MakeActor(robot_mapper, 1.0, 0.82, 0.0);

  trail_data_ = vtkSmartPointer<vtkPolyData>::New();
  auto trail_mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  trail_mapper->SetInputData(trail_data_);
  trail_ = MakeActor(trail_mapper, 1.0, 0.59, 0.12);
  trail_->GetProperty()->SetLineWidth(3.0);
  trail_->GetProperty()->LightingOff();

  path_data_ = vtkSmartPointer<vtkPolyData>::New();
  auto path_mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  path_mapper->SetInputData(path_data_);
  path_ = MakeActor(path_mapper, 0.1, 0.8, 0.3);
  path_->GetProperty()->SetLineWidth(3.0);
  path_->GetProperty()->LightingOff();

  auto sphere = vtkSmartPointer<vtkSphereSource>::New();
  sphere->SetRadius(0.15);
  sphere->SetThetaResolution(16);
  sphere->SetPhiResolution(12);
  auto goal_mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  goal_mapper->SetInputConnection(sphere->GetOutputPort());
  goal_ = MakeActor(goal_mapper, 0.86, 0.12, 0.63);
  goal_->VisibilityOff();
  robot_->VisibilityOff();  // Until the mission reports a pose: before, the camera is unplaced.

  for (vtkActor* actor : {robot_.Get(), trail_.Get(), path_.Get(), goal_.Get()}) {
    renderer->AddActor(actor);
  }
}

MissionOverlay::~MissionOverlay() {
  for (vtkActor* actor : {robot_.Get(), trail_.Get(), path_.Get(), goal_.Get()}) {
    renderer_->RemoveActor(actor);
  }
}

void MissionOverlay::SetRobot(const robotio::Pose2D& pose) {
  robot_->VisibilityOn();
  robot_->SetPosition(pose.x, pose.y, 0.0);
  robot_->SetOrientation(0.0, 0.0, pose.theta * 180.0 / M_PI);
}

void MissionOverlay::SetTrail(const std::vector<robotio::Pose2D>& trail) {
  FillPolyline(trail_data_, trail, [](const robotio::Pose2D& p) { return Eigen::Vector2d(p.x, p.y); });
}

void MissionOverlay::SetPath(const std::vector<Eigen::Vector2d>& path) {
  FillPolyline(path_data_, path, [](const Eigen::Vector2d& p) { return p; });
}

void MissionOverlay::SetGoal(bool has_goal, const Eigen::Vector2d& goal) {
  has_goal_ = has_goal;
  goal_->SetPosition(goal.x(), goal.y(), 0.3);
  goal_->SetVisibility(visible_ && has_goal_);
}

void MissionOverlay::SetVisible(bool visible) {
  visible_ = visible;
  robot_->SetVisibility(visible);
  trail_->SetVisibility(visible);
  path_->SetVisibility(visible);
  goal_->SetVisibility(visible && has_goal_);
}

}  // namespace dynamap::app::gui
