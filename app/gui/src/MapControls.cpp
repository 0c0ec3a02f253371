#include "dynamap/app/gui/MapControls.hpp"

#include <QButtonGroup>
#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QPushButton>
#include <QRadioButton>
#include <QSlider>
#include <QVBoxLayout>
#include <algorithm>
#include <cmath>
#include <limits>

namespace dynamap::app::gui {

namespace {

QLabel* WrappingLabel(const QString& text) {
  auto* label = new QLabel(text);
  label->setWordWrap(true);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  return label;
}

}  // namespace

MapControls::MapControls(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);

  auto* map_group = new QGroupBox(tr("Map"));
  auto* map_layout = new QVBoxLayout(map_group);
  file_label_ = WrappingLabel(tr("No map open. File ▸ Open map… (Ctrl+O)"));
  info_label_ = WrappingLabel(QString());
  map_layout->addWidget(file_label_);
  map_layout->addWidget(info_label_);
  layout->addWidget(map_group);

  auto* layer_group = new QGroupBox(tr("Layers"));
  auto* layer_layout = new QVBoxLayout(layer_group);
  static_box_ = new QCheckBox(tr("Static map"));
  static_box_->setChecked(true);
  dynamic_box_ = new QCheckBox(tr("Dynamic map (red)"));
  dynamic_box_->setChecked(true);
  layer_layout->addWidget(static_box_);
  layer_layout->addWidget(dynamic_box_);
  layout->addWidget(layer_group);
  connect(static_box_, &QCheckBox::toggled, this, &MapControls::FilterChanged);
  connect(dynamic_box_, &QCheckBox::toggled, this, &MapControls::FilterChanged);

  auto* slice_group = new QGroupBox(tr("Height slice (voxel centres)"));
  auto* slice_layout = new QFormLayout(slice_group);
  z_min_spin_ = new QDoubleSpinBox;
  z_max_spin_ = new QDoubleSpinBox;
  z_min_slider_ = new QSlider(Qt::Horizontal);
  z_max_slider_ = new QSlider(Qt::Horizontal);
  for (QDoubleSpinBox* spin : {z_min_spin_, z_max_spin_}) {
    spin->setDecimals(2);
    spin->setSuffix(QStringLiteral(" m"));
    spin->setKeyboardTracking(false);
    connect(spin, qOverload<double>(&QDoubleSpinBox::valueChanged), this,
            &MapControls::OnSliceSpinChanged);
  }
  for (QSlider* slider : {z_min_slider_, z_max_slider_}) {
    connect(slider, &QSlider::valueChanged, this, &MapControls::OnSliceSliderChanged);
  }
  auto* full_button = new QPushButton(tr("Full height"));
  connect(full_button, &QPushButton::clicked, this, [this] { SetSlice(z_lo_, z_hi_); });
  slice_layout->addRow(tr("From"), z_min_spin_);
  slice_layout->addRow(z_min_slider_);
  slice_layout->addRow(tr("To"), z_max_spin_);
  slice_layout->addRow(z_max_slider_);
  slice_layout->addRow(full_button);
  layout->addWidget(slice_group);

  auto* colour_group = new QGroupBox(tr("Colour"));
  auto* colour_layout = new QVBoxLayout(colour_group);
  height_button_ = new QRadioButton(tr("By height"));
  occupancy_button_ = new QRadioButton(tr("By occupancy probability"));
  height_button_->setChecked(true);
  auto* colour_buttons = new QButtonGroup(this);
  colour_buttons->addButton(height_button_);
  colour_buttons->addButton(occupancy_button_);
  colour_layout->addWidget(height_button_);
  colour_layout->addWidget(occupancy_button_);
  layout->addWidget(colour_group);
  connect(height_button_, &QRadioButton::toggled, this, &MapControls::ColourModeChanged);

  auto* pick_group = new QGroupBox(tr("Picked voxel"));
  auto* pick_layout = new QVBoxLayout(pick_group);
  pick_label_ = WrappingLabel(tr("Click a voxel in the view."));
  pick_layout->addWidget(pick_label_);
  layout->addWidget(pick_group);
  layout->addStretch(1);

  SetMap(QString(), nullptr, false);
}

void MapControls::SetMap(const QString& file, const VoxelSet* set, bool dual_map) {
  const bool has_map = set != nullptr;
  if (has_map) {
    file_label_->setText(QStringLiteral("<b>%1</b>").arg(QFileInfo(file).fileName().toHtmlEscaped()));
    file_label_->setToolTip(file);
    const Eigen::Vector3f extent = set->max_corner - set->min_corner;
    info_label_->setText(
        tr("%1, resolution %2 m\n%3 × %4 × %5 m\n%6 static, %7 dynamic voxels")
            .arg(dual_map ? tr("Dual static/dynamic map") : tr("OctoMap (static only)"))
            .arg(set->resolution_m, 0, 'f', 3)
            .arg(extent.x(), 0, 'f', 1)
            .arg(extent.y(), 0, 'f', 1)
            .arg(extent.z(), 0, 'f', 1)
            .arg(set->static_count)
            .arg(set->dynamic_count));
    step_ = set->resolution_m > 0.0 ? set->resolution_m : 0.05;
    z_lo_ = set->voxels.empty() ? 0.0 : set->min_corner.z() + step_ / 2.0;
    z_hi_ = set->voxels.empty() ? 0.0 : set->max_corner.z() - step_ / 2.0;
  } else {
    file_label_->setText(tr("No map open. File ▸ Open map… (Ctrl+O)"));
    file_label_->setToolTip(QString());
    info_label_->clear();
    z_lo_ = z_hi_ = 0.0;
  }
  // A plain OctoMap has no dynamic channel; the toggle would do nothing.
  dynamic_box_->setEnabled(has_map && dual_map);
  static_box_->setEnabled(has_map);
  syncing_ = true;
  const int steps = static_cast<int>(std::lround((z_hi_ - z_lo_) / step_));
  for (QDoubleSpinBox* spin : {z_min_spin_, z_max_spin_}) {
    spin->setRange(z_lo_, z_hi_);
    spin->setSingleStep(step_);
    spin->setEnabled(has_map);
  }
  for (QSlider* slider : {z_min_slider_, z_max_slider_}) {
    slider->setRange(0, std::max(0, steps));
    slider->setEnabled(has_map);
  }
  z_min_spin_->setValue(z_lo_);
  z_max_spin_->setValue(z_hi_);
  syncing_ = false;
  SyncSliders();
  ShowPick(std::nullopt, nullptr);
}

void MapControls::ShowPick(const std::optional<VoxelPick>& pick, const VoxelSet* set) {
  if (!pick || set == nullptr || pick->index >= set->voxels.size()) {
    pick_label_->setText(tr("Click a voxel in the view."));
    return;
  }
  const Voxel& voxel = set->voxels[pick->index];
  pick_label_->setText(
      tr("x %1   y %2   z %3 m\nsize %4 m\nstatic P %5%6\ndynamic P %7%8")
          .arg(voxel.centre.x(), 0, 'f', 3)
          .arg(voxel.centre.y(), 0, 'f', 3)
          .arg(voxel.centre.z(), 0, 'f', 3)
          .arg(voxel.size, 0, 'f', 3)
          .arg(voxel.static_probability, 0, 'f', 3)
          .arg(voxel.static_occupied ? tr(" (occupied)") : QString())
          .arg(voxel.dynamic_probability, 0, 'f', 3)
          .arg(voxel.dynamic_occupied ? tr(" (occupied)") : QString()));
}

void MapControls::SetVisibleCounts(std::size_t static_count, std::size_t dynamic_count) {
  static_box_->setText(tr("Static map (%1 shown)").arg(static_count));
  dynamic_box_->setText(dynamic_box_->isEnabled()
                            ? tr("Dynamic map, red (%1 shown)").arg(dynamic_count)
                            : tr("Dynamic map (none in this file)"));
}

VoxelFilter MapControls::Filter() const {
  VoxelFilter filter;
  filter.show_static = static_box_->isChecked();
  filter.show_dynamic = dynamic_box_->isChecked() && dynamic_box_->isEnabled();
  // Half a step of slack so a voxel centre exactly on the bound stays inside.
  filter.z_min = static_cast<float>(z_min_spin_->value() - step_ / 2.0);
  filter.z_max = static_cast<float>(z_max_spin_->value() + step_ / 2.0);
  if (z_lo_ == z_hi_) {
    filter.z_min = -std::numeric_limits<float>::infinity();
    filter.z_max = std::numeric_limits<float>::infinity();
  }
  return filter;
}

ColourMode MapControls::Colours() const {
  return height_button_->isChecked() ? ColourMode::kHeight : ColourMode::kOccupancy;
}

void MapControls::SetShowStatic(bool show) { static_box_->setChecked(show); }
void MapControls::SetShowDynamic(bool show) { dynamic_box_->setChecked(show); }

void MapControls::SetColourMode(ColourMode mode) {
  (mode == ColourMode::kHeight ? height_button_ : occupancy_button_)->setChecked(true);
}

void MapControls::SetSlice(double z_min, double z_max) {
  syncing_ = true;
  z_min_spin_->setValue(std::clamp(std::min(z_min, z_max), z_lo_, z_hi_));
  z_max_spin_->setValue(std::clamp(std::max(z_min, z_max), z_lo_, z_hi_));
  syncing_ = false;
  SyncSliders();
  emit FilterChanged();
}

bool MapControls::DynamicAvailable() const { return dynamic_box_->isEnabled(); }

QString MapControls::PickText() const { return pick_label_->text(); }

void MapControls::OnSliceSpinChanged() {
  if (syncing_) return;
  // Keep the slice non-empty: moving one bound past the other drags it along.
  syncing_ = true;
  if (sender() == z_min_spin_ && z_min_spin_->value() > z_max_spin_->value()) {
    z_max_spin_->setValue(z_min_spin_->value());
  } else if (sender() == z_max_spin_ && z_max_spin_->value() < z_min_spin_->value()) {
    z_min_spin_->setValue(z_max_spin_->value());
  }
  syncing_ = false;
  SyncSliders();
  emit FilterChanged();
}

void MapControls::OnSliceSliderChanged() {
  if (syncing_) return;
  const auto* slider = qobject_cast<QSlider*>(sender());
  QDoubleSpinBox* spin = slider == z_min_slider_ ? z_min_spin_ : z_max_spin_;
  spin->setValue(z_lo_ + slider->value() * step_);
}

void MapControls::SyncSliders() {
  syncing_ = true;
  z_min_slider_->setValue(static_cast<int>(std::lround((z_min_spin_->value() - z_lo_) / step_)));
  z_max_slider_->setValue(static_cast<int>(std::lround((z_max_spin_->value() - z_lo_) / step_)));
  syncing_ = false;
}

}  // namespace dynamap::app::gui
