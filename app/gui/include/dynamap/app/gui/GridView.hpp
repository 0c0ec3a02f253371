// The 2D view of a mission: the projected grid (planning::GridMap; navigable, obstacle,
// hole, unknown), the trail, the planned path, the target candidates, the frontier regions
// passed over, the current goal and the robot, north up and scaled to fit. Painted from
// plain values of a snapshot.
#pragma once

#include <Eigen/Core>
#include <QImage>
#include <QWidget>
#include <memory>
#include <vector>

#include "dynamap/planning/GridMap.hpp"
#include "dynamap/robotio/Pose2D.hpp"

namespace dynamap::app::gui {

struct GridScene {
  std::shared_ptr<const planning::GridMap> grid;  // null: nothing projected yet.
  robotio::Pose2D pose;                           // Robot, map frame.
  std::vector<robotio::Pose2D> trail;             // Path driven, map frame.
  std::vector<Eigen::Vector2d> path;              // Planned path, m, map frame.
  std::vector<Eigen::Vector2d> candidates;        // Target viewpoints, m, map frame.
  // Frontier regions the planner passed over (centres, m, map frame), drawn as crosses.
  std::vector<Eigen::Vector2d> unreachable_frontiers;  // No viewpoint reachable: red.
  std::vector<Eigen::Vector2d> blacklisted_frontiers;  // Given up after failed tries: blue.
  bool has_goal = false;
  Eigen::Vector2d goal = Eigen::Vector2d::Zero();  // m, map frame.
};

// One ARGB pixel per cell, row 0 at the top (north up); unknown cells transparent grey.
[[nodiscard]] QImage GridToImage(const planning::GridMap& grid);

class GridView : public QWidget {
  Q_OBJECT

 public:
  explicit GridView(QWidget* parent = nullptr);

  void SetScene(GridScene scene);
  [[nodiscard]] const GridScene& Scene() const { return scene_; }
  [[nodiscard]] QSize sizeHint() const override { return {360, 240}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  GridScene scene_;
  QImage image_;  // of scene_.grid, rebuilt only when the grid changes.
  const planning::GridMap* image_of_ = nullptr;
};

}  // namespace dynamap::app::gui
