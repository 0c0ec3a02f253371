#include "dynamap/app/gui/VoxelView.hpp"

#include <QApplication>
#include <QMouseEvent>
#include <QVTKInteractor.h>
#include <vtkActor.h>
#include <vtkAxesActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkCubeSource.h>
#include <vtkFloatArray.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGlyph3DMapper.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkLightKit.h>
#include <vtkLookupTable.h>
#include <vtkOrientationMarkerWidget.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

namespace dynamap::app::gui {

namespace {

// A click is a pick, not a rotation, when the cursor moved at most this far (pixels).
constexpr int kClickSlopPx = 4;
constexpr std::array<double, 3> kDynamicRgb = {0.91, 0.16, 0.16};
// Points drawn while dragging. Software OpenGL (llvmpipe) rasterises a wide point as two
// triangles: 1 px points rotate an office map three times faster there (docs/BENCHMARKS.md).
constexpr float kDragPointSizePx = 3.0f;
constexpr float kSoftwareDragPointSizePx = 1.0f;

bool IsSoftwareRenderer(vtkRenderWindow* window) {
  const std::string capabilities = window->ReportCapabilities();
  for (const char* name : {"llvmpipe", "softpipe", "Software Rasterizer", "SWR"}) {
    if (capabilities.find(name) != std::string::npos) return true;
  }
  return false;
}

vtkSmartPointer<vtkLookupTable> MakeHeightLut() {
  // Viridis: readable in grey print and leaves red free for the dynamic layer.
  constexpr std::array<std::array<double, 3>, 5> kStops = {{{0.267, 0.005, 0.329},
                                                            {0.229, 0.322, 0.546},
                                                            {0.128, 0.567, 0.551},
                                                            {0.369, 0.789, 0.383},
                                                            {0.993, 0.906, 0.144}}};
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  constexpr int kEntries = 256;
  lut->SetNumberOfTableValues(kEntries);
  for (int i = 0; i < kEntries; ++i) {
    const double s = static_cast<double>(i) / (kEntries - 1) * (kStops.size() - 1);
    const auto k = std::min<std::size_t>(static_cast<std::size_t>(s), kStops.size() - 2);
    const double f = s - static_cast<double>(k);
    lut->SetTableValue(i, kStops[k][0] + f * (kStops[k + 1][0] - kStops[k][0]),
                       kStops[k][1] + f * (kStops[k + 1][1] - kStops[k][1]),
                       kStops[k][2] + f * (kStops[k + 1][2] - kStops[k][2]), 1.0);
  }
  lut->Build();
  return lut;
}

vtkSmartPointer<vtkLookupTable> MakeOccupancyLut() {
  // Light (barely occupied) to dark (certain), like octovis' occupancy shading.
  auto lut = vtkSmartPointer<vtkLookupTable>::New();
  lut->SetNumberOfTableValues(256);
  lut->SetHueRange(0.58, 0.58);
  lut->SetSaturationRange(0.15, 0.55);
  lut->SetValueRange(0.95, 0.25);
  lut->SetTableRange(0.5, 1.0);
  lut->Build();
  return lut;
}

vtkSmartPointer<vtkGlyph3DMapper> MakeCubeMapper() {
  auto cube = vtkSmartPointer<vtkCubeSource>::New();
  cube->SetXLength(1.0);
  cube->SetYLength(1.0);
  cube->SetZLength(1.0);
  auto mapper = vtkSmartPointer<vtkGlyph3DMapper>::New();
  mapper->SetSourceConnection(cube->GetOutputPort());
  mapper->SetScaleArray("size");
  mapper->SetScaleModeToScaleByMagnitude();
  mapper->ScalingOn();
  mapper->OrientOff();
  mapper->SetInputData(vtkSmartPointer<vtkPolyData>::New());
  return mapper;
}

}  // namespace

VoxelView::VoxelView(QWidget* parent) : QVTKOpenGLNativeWidget(parent) {
  auto window = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
  // No multisampling: it more than doubles the cost of a frame on software OpenGL, and
  // axis-aligned cubes shaded per face show little aliasing.
  window->SetMultiSamples(0);
  setRenderWindow(window);
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderer_->GradientBackgroundOn();
  renderer_->SetBackground(0.10, 0.11, 0.13);
  renderer_->SetBackground2(0.27, 0.30, 0.35);
  window->AddRenderer(renderer_);
  // Key, fill and back lights give the three visible faces of a cube three different
  // shades; with the default headlight, walls and floors read as flat colour.
  auto light_kit = vtkSmartPointer<vtkLightKit>::New();
  light_kit->AddLightsToRenderer(renderer_);

  height_lut_ = MakeHeightLut();
  occupancy_lut_ = MakeOccupancyLut();
  static_mapper_ = MakeCubeMapper();
  dynamic_mapper_ = MakeCubeMapper();
  dynamic_mapper_->ScalarVisibilityOff();

  static_actor_ = vtkSmartPointer<vtkActor>::New();
  static_actor_->SetMapper(static_mapper_);
  static_actor_->GetProperty()->SetAmbient(0.25);
  static_actor_->GetProperty()->SetDiffuse(0.8);
  dynamic_actor_ = vtkSmartPointer<vtkActor>::New();
  dynamic_actor_->SetMapper(dynamic_mapper_);
  dynamic_actor_->GetProperty()->SetColor(kDynamicRgb[0], kDynamicRgb[1], kDynamicRgb[2]);
  dynamic_actor_->GetProperty()->SetAmbient(0.3);
  renderer_->AddActor(static_actor_);
  renderer_->AddActor(dynamic_actor_);

  static_points_mapper_ = vtkSmartPointer<vtkPolyDataMapper>::New();
  dynamic_points_mapper_ = vtkSmartPointer<vtkPolyDataMapper>::New();
  dynamic_points_mapper_->ScalarVisibilityOff();
  static_points_actor_ = vtkSmartPointer<vtkActor>::New();
  static_points_actor_->SetMapper(static_points_mapper_);
  dynamic_points_actor_ = vtkSmartPointer<vtkActor>::New();
  dynamic_points_actor_->SetMapper(dynamic_points_mapper_);
  dynamic_points_actor_->GetProperty()->SetColor(kDynamicRgb[0], kDynamicRgb[1], kDynamicRgb[2]);
  for (vtkActor* actor : {static_points_actor_.Get(), dynamic_points_actor_.Get()}) {
    actor->GetProperty()->SetRepresentationToPoints();
    actor->GetProperty()->SetPointSize(kDragPointSizePx);
    actor->GetProperty()->LightingOff();
    actor->VisibilityOff();
    actor->PickableOff();
    renderer_->AddActor(actor);
  }

  auto highlight_source = vtkSmartPointer<vtkCubeSource>::New();
  auto highlight_mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
  highlight_mapper->SetInputConnection(highlight_source->GetOutputPort());
  highlight_actor_ = vtkSmartPointer<vtkActor>::New();
  highlight_actor_->SetMapper(highlight_mapper);
  highlight_actor_->GetProperty()->SetRepresentationToWireframe();
  highlight_actor_->GetProperty()->SetColor(1.0, 0.85, 0.1);
  highlight_actor_->GetProperty()->SetLineWidth(3.0);
  highlight_actor_->GetProperty()->LightingOff();
  highlight_actor_->VisibilityOff();
  highlight_actor_->PickableOff();
  renderer_->AddActor(highlight_actor_);

  scalar_bar_ = vtkSmartPointer<vtkScalarBarActor>::New();
  scalar_bar_->SetNumberOfLabels(5);
  scalar_bar_->SetBarRatio(0.25);
  scalar_bar_->SetPosition(0.925, 0.08);
  scalar_bar_->SetWidth(0.065);
  scalar_bar_->SetHeight(0.55);
  scalar_bar_->UnconstrainedFontSizeOn();
  scalar_bar_->GetTitleTextProperty()->SetFontSize(14);
  scalar_bar_->GetTitleTextProperty()->ItalicOff();
  scalar_bar_->GetTitleTextProperty()->ShadowOff();
  scalar_bar_->GetLabelTextProperty()->SetFontSize(13);
  scalar_bar_->GetLabelTextProperty()->ItalicOff();
  scalar_bar_->GetLabelTextProperty()->ShadowOff();
  scalar_bar_->GetLabelTextProperty()->BoldOff();
  scalar_bar_->VisibilityOff();
  renderer_->AddViewProp(scalar_bar_);

  auto style = vtkSmartPointer<vtkInteractorStyleTrackballCamera>::New();
  interactor()->SetInteractorStyle(style);
  // The trackball style brackets every drag and wheel step with these two events.
  style->AddObserver(vtkCommand::StartInteractionEvent, this, &VoxelView::OnStartInteraction);
  style->AddObserver(vtkCommand::EndInteractionEvent, this, &VoxelView::OnEndInteraction);
  axes_widget_ = vtkSmartPointer<vtkOrientationMarkerWidget>::New();
  axes_widget_->SetOrientationMarker(vtkSmartPointer<vtkAxesActor>::New());
  axes_widget_->SetInteractor(interactor());
  axes_widget_->SetViewport(0.0, 0.0, 0.16, 0.22);
  axes_widget_->SetEnabled(1);
  axes_widget_->InteractiveOff();

  ApplyColourMode();
}

VoxelView::~VoxelView() = default;

void VoxelView::SetVoxels(std::shared_ptr<const VoxelSet> set, const VoxelFilter& filter,
                          ColourMode mode, bool reset_camera) {
  set_ = std::move(set);
  filter_ = filter;
  colour_mode_ = mode;
  highlight_actor_->VisibilityOff();
  RebuildLayers();
  ApplyColourMode();
  if (reset_camera) {
    ResetCamera();
  } else {
    Render();
  }
}

void VoxelView::SetFilter(const VoxelFilter& filter) {
  filter_ = filter;
  RebuildLayers();
  Render();
}

void VoxelView::SetColourMode(ColourMode mode) {
  colour_mode_ = mode;
  RebuildLayers();
  ApplyColourMode();
  Render();
}

void VoxelView::ResetCamera() {
  vtkCamera* camera = renderer_->GetActiveCamera();
  Eigen::Vector3f centre = Eigen::Vector3f::Zero();
  float extent = 5.0f;
  if (set_ && !set_->voxels.empty()) {
    centre = (set_->min_corner + set_->max_corner) / 2.0f;
    extent = std::max(1.0f, (set_->max_corner - set_->min_corner).norm());
  }
  // An oblique view from the south-west, z up, as an operator looks over a floor plan.
  camera->SetFocalPoint(centre.x(), centre.y(), centre.z());
  camera->SetPosition(centre.x() - 0.55 * extent, centre.y() - 0.75 * extent,
                      centre.z() + 0.65 * extent);
  camera->SetViewUp(0.0, 0.0, 1.0);
  if (set_ && !set_->voxels.empty()) {
    // Keep the direction, move so the whole map fits, then come a little closer: the
    // bounding sphere VTK fits is loose for a flat floor plan.
    renderer_->ResetCamera(set_->min_corner.x(), set_->max_corner.x(), set_->min_corner.y(),
                           set_->max_corner.y(), set_->min_corner.z(), set_->max_corner.z());
    camera->Dolly(1.25);
  }
  renderer_->ResetCameraClippingRange();
  Render();
}

void VoxelView::SetHighlight(std::optional<std::uint32_t> index) {
  if (!index || !set_ || *index >= set_->voxels.size()) {
    highlight_actor_->VisibilityOff();
  } else {
    const Voxel& voxel = set_->voxels[*index];
    auto* source = vtkCubeSource::SafeDownCast(
        highlight_actor_->GetMapper()->GetInputAlgorithm());
    const double edge = voxel.size * 1.15;
    source->SetCenter(voxel.centre.x(), voxel.centre.y(), voxel.centre.z());
    source->SetXLength(edge);
    source->SetYLength(edge);
    source->SetZLength(edge);
    highlight_actor_->VisibilityOn();
  }
  Render();
}

void VoxelView::RotateAndRender(double degrees) {
  renderer_->GetActiveCamera()->Azimuth(degrees);
  renderer_->ResetCameraClippingRange();
  renderWindow()->Render();
}

void VoxelView::SetInteracting(bool interacting) {
  ShowPoints(interacting);
  Render();
}

void VoxelView::ShowPoints(bool points) {
  if (points && !renderer_checked_) {
    renderer_checked_ = true;
    if (IsSoftwareRenderer(renderWindow())) {
      static_points_actor_->GetProperty()->SetPointSize(kSoftwareDragPointSizePx);
      dynamic_points_actor_->GetProperty()->SetPointSize(kSoftwareDragPointSizePx);
    }
  }
  interacting_ = points;
  static_actor_->SetVisibility(!points);
  dynamic_actor_->SetVisibility(!points);
  static_points_actor_->SetVisibility(points);
  dynamic_points_actor_->SetVisibility(points);
}

void VoxelView::OnStartInteraction() {
  // A wheel step is a single frame; switching to points and back would cost two.
  if (QApplication::mouseButtons() != Qt::NoButton) ShowPoints(true);
}

void VoxelView::OnEndInteraction() {
  if (interacting_) SetInteracting(false);
}

vtkRenderer* VoxelView::Renderer() const { return renderer_; }

std::size_t VoxelView::VisibleCount(VoxelLayer layer) const {
  return layer == VoxelLayer::kStatic ? visible_static_ : visible_dynamic_;
}

std::optional<VoxelPick> VoxelView::PickAt(const QPoint& position) {
  if (!set_) return std::nullopt;
  const double ratio = effectiveDevicePixelRatio();
  const int* size = renderWindow()->GetSize();
  const double x = position.x() * ratio;
  const double y = size[1] - 1 - position.y() * ratio;
  std::array<Eigen::Vector3f, 2> ends;
  for (int i = 0; i < 2; ++i) {
    renderer_->SetDisplayPoint(x, y, i == 0 ? 0.0 : 1.0);
    renderer_->DisplayToWorld();
    const double* w = renderer_->GetWorldPoint();
    if (w[3] == 0.0) return std::nullopt;
    ends[i] = Eigen::Vector3f(static_cast<float>(w[0] / w[3]), static_cast<float>(w[1] / w[3]),
                              static_cast<float>(w[2] / w[3]));
  }
  return PickVoxel(*set_, filter_, ends[0], ends[1] - ends[0]);
}

void VoxelView::mousePressEvent(QMouseEvent* event) {
  press_position_ = event->pos();
  QVTKOpenGLNativeWidget::mousePressEvent(event);
}

void VoxelView::mouseReleaseEvent(QMouseEvent* event) {
  QVTKOpenGLNativeWidget::mouseReleaseEvent(event);
  if (event->button() != Qt::LeftButton) return;
  if ((event->pos() - press_position_).manhattanLength() > kClickSlopPx) return;
  const auto pick = PickAt(event->pos());
  SetHighlight(pick ? std::optional<std::uint32_t>(pick->index) : std::nullopt);
  emit VoxelPicked(pick);
}

void VoxelView::RebuildLayers() {
  const bool by_height = colour_mode_ == ColourMode::kHeight;
  for (const VoxelLayer layer : {VoxelLayer::kStatic, VoxelLayer::kDynamic}) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->SetDataTypeToFloat();
    auto sizes = vtkSmartPointer<vtkFloatArray>::New();
    sizes->SetName("size");
    auto values = vtkSmartPointer<vtkFloatArray>::New();
    values->SetName(by_height ? "height" : "occupancy");
    std::size_t count = 0;
    if (set_) {
      const auto indices = VisibleIndices(*set_, layer, filter_);
      count = indices.size();
      points->SetNumberOfPoints(static_cast<vtkIdType>(count));
      sizes->SetNumberOfValues(static_cast<vtkIdType>(count));
      values->SetNumberOfValues(static_cast<vtkIdType>(count));
      for (std::size_t i = 0; i < count; ++i) {
        const Voxel& voxel = set_->voxels[indices[i]];
        const auto id = static_cast<vtkIdType>(i);
        points->SetPoint(id, voxel.centre.x(), voxel.centre.y(), voxel.centre.z());
        sizes->SetValue(id, voxel.size);
        values->SetValue(id, by_height ? voxel.centre.z() : voxel.static_probability);
      }
    }
    // One vertex cell per voxel for the points drawn while dragging; the glyph mapper
    // ignores cells.
    auto verts = vtkSmartPointer<vtkCellArray>::New();
    verts->AllocateExact(static_cast<vtkIdType>(count), static_cast<vtkIdType>(count));
    for (std::size_t i = 0; i < count; ++i) {
      const auto id = static_cast<vtkIdType>(i);
      verts->InsertNextCell(1, &id);
    }
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetVerts(verts);
    poly->GetPointData()->AddArray(sizes);
    poly->GetPointData()->SetScalars(values);
    if (layer == VoxelLayer::kStatic) {
      static_mapper_->SetInputData(poly);
      static_points_mapper_->SetInputData(poly);
      visible_static_ = count;
    } else {
      dynamic_mapper_->SetInputData(poly);
      dynamic_points_mapper_->SetInputData(poly);
      visible_dynamic_ = count;
    }
  }
}

void VoxelView::ApplyColourMode() {
  if (colour_mode_ == ColourMode::kHeight) {
    double z_lo = 0.0;
    double z_hi = 1.0;
    if (set_ && !set_->voxels.empty()) {
      const double half_leaf = set_->resolution_m / 2.0;
      z_lo = set_->min_corner.z() + half_leaf;
      z_hi = std::max(z_lo + 1e-3, static_cast<double>(set_->max_corner.z()) - half_leaf);
    }
    height_lut_->SetTableRange(z_lo, z_hi);
    static_mapper_->SetLookupTable(height_lut_);
    static_mapper_->SetScalarRange(z_lo, z_hi);
    scalar_bar_->SetLookupTable(height_lut_);
    scalar_bar_->SetTitle("height (m)");
    scalar_bar_->SetLabelFormat("%.1f");
  } else {
    static_mapper_->SetLookupTable(occupancy_lut_);
    static_mapper_->SetScalarRange(0.5, 1.0);
    scalar_bar_->SetLookupTable(occupancy_lut_);
    scalar_bar_->SetTitle("P(occupied)");
    scalar_bar_->SetLabelFormat("%.2f");
  }
  static_mapper_->ScalarVisibilityOn();
  static_mapper_->SetScalarModeToUsePointData();
  static_mapper_->UseLookupTableScalarRangeOff();
  static_points_mapper_->SetLookupTable(static_mapper_->GetLookupTable());
  static_points_mapper_->SetScalarRange(static_mapper_->GetScalarRange());
  static_points_mapper_->ScalarVisibilityOn();
  static_points_mapper_->SetScalarModeToUsePointData();
  scalar_bar_->SetVisibility(set_ && !set_->voxels.empty());
}

void VoxelView::Render() {
  renderer_->ResetCameraClippingRange();
  renderWindow()->Render();
  update();
}

}  // namespace dynamap::app::gui
