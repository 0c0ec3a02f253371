// What the Mission workspace draws over the 3D map: the robot (a disc of its footprint and
// a heading arrow), its trail, the planned path and the goal, as a few VTK actors added to
// a VoxelView's renderer and updated from snapshots.
#pragma once

#include <Eigen/Core>
#include <vtkSmartPointer.h>

#include <vector>

#include "dynamap/robotio/Pose2D.hpp"

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace dynamap::app::gui {

class MissionOverlay {
 public:
  MissionOverlay(vtkRenderer* renderer, double robot_radius_m);
  // Takes its actors out of the renderer.
  ~MissionOverlay();
  MissionOverlay(const MissionOverlay&) = delete;
  MissionOverlay& operator=(const MissionOverlay&) = delete;

  void SetRobot(const robotio::Pose2D& pose);
  void SetTrail(const std::vector<robotio::Pose2D>& trail);
  void SetPath(const std::vector<Eigen::Vector2d>& path);
  void SetGoal(bool has_goal, const Eigen::Vector2d& goal);
  void SetVisible(bool visible);

 private:
  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkActor> robot_;
  vtkSmartPointer<vtkActor> trail_;
  vtkSmartPointer<vtkActor> path_;
  vtkSmartPointer<vtkActor> goal_;
  vtkSmartPointer<vtkPolyData> trail_data_;
  vtkSmartPointer<vtkPolyData> path_data_;
  bool visible_ = true;
  bool has_goal_ = false;
};

}  // namespace dynamap::app::gui
