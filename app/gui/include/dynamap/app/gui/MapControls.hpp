// The Maps workspace's side panel: what the open map is, which layers show, the height
// slice, the colour mode and the picked voxel. It holds no map data, only the choices.
#pragma once

#include <QWidget>
#include <optional>

#include "dynamap/app/gui/VoxelSet.hpp"
#include "dynamap/app/gui/VoxelView.hpp"

class QButtonGroup;
class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QRadioButton;
class QSlider;

namespace dynamap::app::gui {

class MapControls : public QWidget {
  Q_OBJECT

 public:
  explicit MapControls(QWidget* parent = nullptr);

  // Describes the open map (nullptr: none) and resets the slice to its full height.
  void SetMap(const QString& file, const VoxelSet* set, bool dual_map);
  void ShowPick(const std::optional<VoxelPick>& pick, const VoxelSet* set);
  void SetVisibleCounts(std::size_t static_count, std::size_t dynamic_count);

  [[nodiscard]] VoxelFilter Filter() const;
  [[nodiscard]] ColourMode Colours() const;
  void SetShowStatic(bool show);
  void SetShowDynamic(bool show);
  void SetColourMode(ColourMode mode);
  // Metres, map frame; clamped to the map's height range.
  void SetSlice(double z_min, double z_max);
  [[nodiscard]] bool DynamicAvailable() const;
  [[nodiscard]] QString PickText() const;

 signals:
  void FilterChanged();
  void ColourModeChanged();

 private:
  void OnSliceSpinChanged();
  void OnSliceSliderChanged();
  void SyncSliders();

  QLabel* file_label_ = nullptr;
  QLabel* info_label_ = nullptr;
  QCheckBox* static_box_ = nullptr;
  QCheckBox* dynamic_box_ = nullptr;
  QDoubleSpinBox* z_min_spin_ = nullptr;
  QDoubleSpinBox* z_max_spin_ = nullptr;
  QSlider* z_min_slider_ = nullptr;
  QSlider* z_max_slider_ = nullptr;
  QRadioButton* height_button_ = nullptr;
  QRadioButton* occupancy_button_ = nullptr;
  QLabel* pick_label_ = nullptr;
  double z_lo_ = 0.0;  // m, the map's height range.
  double z_hi_ = 0.0;
  double step_ = 0.05;  // m, one slider step = one leaf.
  bool syncing_ = false;
};

}  // namespace dynamap::app::gui
