// The Mission workspace: run an autonomous exploration in the simulator and watch it live —
// the 3D map (static by height, dynamic red; as the runtime last saved it) with the robot,
// trail, path and goal; the projected grid with candidates, goal and path; both depth
// images; the live figures; the report at the end.
#pragma once

#include <QString>
#include <QWidget>
#include <memory>
#include <optional>

#include "dynamap/app/gui/MissionSession.hpp"
#include "dynamap/app/runtime/MissionConfig.hpp"

namespace dynamap::app::gui {

// A mission to start without the operator (`dynamap gui --explore`); what is left empty
// keeps the panel's setting.
struct ExploreRequest {
  QString world_file;                        // selected, and added to the list if not shipped.
  QString out_dir;                           // results folder; empty: a new one per mission.
  std::optional<double> max_time_s;          // simulated time limit, s.
  std::optional<runtime::PoseSource> poses;  // where frames are placed from.
  std::optional<int> kinect_width;           // Kinect image width, px; the height is 3/4 of it.
};

class DepthPreview;
class GridView;
class MissionOverlay;
class MissionPanel;
class VoxelView;

class MissionWorkspace : public QWidget {
  Q_OBJECT

 public:
  explicit MissionWorkspace(QWidget* parent = nullptr);
  ~MissionWorkspace() override;

  // What the buttons do; false when the session refuses in its current phase.
  bool StartMission();
  bool PauseMission();
  bool ResumeMission();
  bool StopMission();
  // Sets the panel up from `request` and presses Start; false when the session refuses.
  bool Explore(const ExploreRequest& request);

  [[nodiscard]] MissionSession* Session() const { return session_; }
  [[nodiscard]] MissionPanel* Panel() const { return panel_; }
  [[nodiscard]] VoxelView* View() const { return view_; }
  [[nodiscard]] GridView* Grid() const { return grid_; }
  [[nodiscard]] DepthPreview* Depth(int index) const { return index == 0 ? depth0_ : depth1_; }

 signals:
  // For the status bar: phase name and dropped frames (nullopt without a mission).
  void StatusChanged(const QString& state, std::optional<std::uint64_t> dropped);
  void ErrorOccurred(const QString& message);

 private:
  void OnPhaseChanged(MissionPhase phase);
  void OnSnapshot();
  void OnMapUpdated();

  MissionSession* session_ = nullptr;
  MissionPanel* panel_ = nullptr;
  VoxelView* view_ = nullptr;
  GridView* grid_ = nullptr;
  DepthPreview* depth0_ = nullptr;
  DepthPreview* depth1_ = nullptr;
  std::unique_ptr<MissionOverlay> overlay_;
  std::vector<bool> upside_down_;  // Per Kinect of the mission's rig.
  bool camera_placed_ = false;
};

}  // namespace dynamap::app::gui
