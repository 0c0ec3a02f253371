// A live depth image of one Kinect: depth in metres coloured near (warm) to far (cool),
// missing returns black, optionally with the fitted floor plane's inliers tinted green, and
// turned upright for a Kinect mounted upside down. Shared by the Mission and Calibration
// workspaces.
#pragma once

#include <Eigen/Core>
#include <QImage>
#include <QString>
#include <QWidget>
#include <optional>

#include "dynamap/robotio/DepthFrame.hpp"

namespace dynamap::app::gui {

// A plane n·p + d = 0 in the Kinect's optical frame (n unit length), m.
struct DepthPlane {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitY();
  double distance_m = 0.0;
  double band_m = 0.03;  // m, points this close to the plane are tinted.
};

struct DepthImageOptions {
  double max_range_m = 4.5;          // m, depth mapped to the far end of the colour ramp.
  bool rotate_180 = false;           // Kinect mounted upside down (roll near 180°).
  std::optional<DepthPlane> plane;   // Tint the plane's inliers.
};

[[nodiscard]] QImage DepthToImage(const robotio::DepthFrame& frame,
                                  const DepthImageOptions& options);

class DepthPreview : public QWidget {
  Q_OBJECT

 public:
  explicit DepthPreview(const QString& title, QWidget* parent = nullptr);

  void SetFrame(const robotio::DepthFrame& frame, const DepthImageOptions& options);
  void Clear();
  [[nodiscard]] const QImage& Image() const { return image_; }
  [[nodiscard]] QSize sizeHint() const override { return {240, 200}; }

 protected:
  void paintEvent(QPaintEvent* event) override;

 private:
  QString title_;
  QString caption_;
  QImage image_;
};

}  // namespace dynamap::app::gui
