// The 3D view of a voxel map: each layer (static, dynamic) is one polydata of voxel centres
// drawn by a vtkGlyph3DMapper with a cube source (GPU instancing), never an actor per voxel.
// While the operator drags, the same polydata is drawn as points (one vertex instead of 12
// triangles per voxel; 1 px points on software OpenGL), so rotation stays interactive on
// software OpenGL too. Left click without dragging picks the voxel under the cursor.
#pragma once

#include <QPoint>
#include <QVTKOpenGLNativeWidget.h>
#include <vtkSmartPointer.h>

#include <cstddef>
#include <memory>
#include <optional>

#include "dynamap/app/gui/VoxelSet.hpp"

class vtkActor;
class vtkGlyph3DMapper;
class vtkLookupTable;
class vtkOrientationMarkerWidget;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkScalarBarActor;

namespace dynamap::app::gui {

enum class ColourMode {
  kHeight,     // static voxels by centre height (viridis), dynamic voxels red.
  kOccupancy,  // static voxels by occupancy probability (grey ramp), dynamic voxels red.
};

class VoxelView : public QVTKOpenGLNativeWidget {
  Q_OBJECT

 public:
  explicit VoxelView(QWidget* parent = nullptr);
  ~VoxelView() override;

  // Shows `set` (nullptr clears the view) with `filter` and `mode`, and frames it when
  // `reset_camera`.
  void SetVoxels(std::shared_ptr<const VoxelSet> set, const VoxelFilter& filter,
                 ColourMode mode, bool reset_camera);
  void SetFilter(const VoxelFilter& filter);
  void SetColourMode(ColourMode mode);
  void ResetCamera();
  // Highlights one voxel (nullopt removes the highlight).
  void SetHighlight(std::optional<std::uint32_t> index);

  // Rotates the camera about the view-up axis by `degrees` and renders one frame; used by
  // the rotation benchmark to time what an operator's drag does.
  void RotateAndRender(double degrees);
  // Points while true (during a drag), cubes otherwise; renders.
  void SetInteracting(bool interacting);
  [[nodiscard]] bool Interacting() const { return interacting_; }

  // For overlays drawn in the same scene (the mission's robot, trail and path).
  [[nodiscard]] vtkRenderer* Renderer() const;
  // Renders one frame now (after overlays changed).
  void Render();

  [[nodiscard]] std::size_t VisibleCount(VoxelLayer layer) const;
  [[nodiscard]] const VoxelFilter& Filter() const { return filter_; }
  [[nodiscard]] ColourMode Colours() const { return colour_mode_; }

  // The first visible voxel under widget pixel `position` (logical pixels).
  [[nodiscard]] std::optional<VoxelPick> PickAt(const QPoint& position);

 signals:
  void VoxelPicked(std::optional<dynamap::app::gui::VoxelPick> pick);

 protected:
  void mousePressEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;

 private:
  void ShowPoints(bool points);
  void OnStartInteraction();
  void OnEndInteraction();
  void RebuildLayers();
  void ApplyColourMode();

  std::shared_ptr<const VoxelSet> set_;
  VoxelFilter filter_;
  ColourMode colour_mode_ = ColourMode::kHeight;
  std::size_t visible_static_ = 0;
  std::size_t visible_dynamic_ = 0;
  QPoint press_position_;
  bool interacting_ = false;
  bool renderer_checked_ = false;  // point size chosen for the OpenGL implementation.

  vtkSmartPointer<vtkRenderer> renderer_;
  vtkSmartPointer<vtkGlyph3DMapper> static_mapper_;
  vtkSmartPointer<vtkGlyph3DMapper> dynamic_mapper_;
  vtkSmartPointer<vtkActor> static_actor_;
  vtkSmartPointer<vtkActor> dynamic_actor_;
  vtkSmartPointer<vtkPolyDataMapper> static_points_mapper_;
  vtkSmartPointer<vtkPolyDataMapper> dynamic_points_mapper_;
  vtkSmartPointer<vtkActor> static_points_actor_;
  vtkSmartPointer<vtkActor> dynamic_points_actor_;
  vtkSmartPointer<vtkActor> highlight_actor_;
  vtkSmartPointer<vtkLookupTable> height_lut_;
  vtkSmartPointer<vtkLookupTable> occupancy_lut_;
  vtkSmartPointer<vtkScalarBarActor> scalar_bar_;
  vtkSmartPointer<vtkOrientationMarkerWidget> axes_widget_;
};

}  // namespace dynamap::app::gui
