#include "dynamap/app/gui/GridView.hpp"

#include <QPainter>
#include <QPainterPath>
#include <algorithm>
#include <cmath>

namespace dynamap::app::gui {

namespace {

QRgb CellColour(planning::CellState state) {
  switch (state) {
    case planning::CellState::kNavigable:
      return qRgb(245, 245, 240);
    case planning::CellState::kObstacle:
      return qRgb(40, 40, 48);
    case planning::CellState::kHole:
      return qRgb(70, 110, 200);
    case planning::CellState::kUnknown:
      break;
  }
  return qRgb(150, 152, 158);
}

}  // namespace

QImage GridToImage(const planning::GridMap& grid) {
  QImage image(grid.width, grid.height, QImage::Format_RGB32);
  for (int y = 0; y < grid.height; ++y) {
    auto* row = reinterpret_cast<QRgb*>(image.scanLine(grid.height - 1 - y));
    for (int x = 0; x < grid.width; ++x) row[x] = CellColour(grid.At({x, y}));
  }
  return image;
}

GridView::GridView(QWidget* parent) : QWidget(parent) {
  setMinimumSize(200, 140);
  setAttribute(Qt::WA_OpaquePaintEvent);
}

void GridView::SetScene(GridScene scene) {
  scene_ = std::move(scene);
  if (scene_.grid.get() != image_of_) {
    image_of_ = scene_.grid.get();
    image_ = scene_.grid ? GridToImage(*scene_.grid) : QImage();
  }
  update();
}

void GridView::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(38, 40, 46));
  if (!scene_.grid || image_.isNull()) {
    painter.setPen(QColor(200, 200, 200));
    painter.drawText(rect(), Qt::AlignCenter, tr("No projected map yet"));
    return;
  }
  const planning::GridMap& grid = *scene_.grid;
  const double scale = std::min(width() / static_cast<double>(grid.width),
                                height() / static_cast<double>(grid.height));
  const double left = (width() - grid.width * scale) / 2.0;
  const double top = (height() - grid.height * scale) / 2.0;
  painter.drawImage(QRectF(left, top, grid.width * scale, grid.height * scale), image_);

  // Map frame metres to widget pixels (north up).
  const double px_per_m = scale / grid.resolution_m;
  const auto to_px = [&](double x, double y) {
    return QPointF(left + (x - grid.origin_x_m) * px_per_m,
                   top + grid.height * scale - (y - grid.origin_y_m) * px_per_m);
  };
  painter.setRenderHint(QPainter::Antialiasing);
  if (scene_.trail.size() > 1) {
    QPainterPath trail(to_px(scene_.trail.front().x, scene_.trail.front().y));
    for (const auto& p : scene_.trail) trail.lineTo(to_px(p.x, p.y));
    painter.setPen(QPen(QColor(255, 150, 30), 2.0));
    painter.drawPath(trail);
  }
  painter.setPen(QPen(QColor(20, 90, 200), 1.0));
  painter.setBrush(QColor(90, 170, 255));
  for (const auto& c : scene_.candidates) painter.drawEllipse(to_px(c.x(), c.y()), 3.5, 3.5);
  const auto cross = [&](const Eigen::Vector2d& c, const QColor& colour) {
    const QPointF p = to_px(c.x(), c.y());
    painter.setPen(QPen(colour, 2.5));
    painter.drawLine(p + QPointF(-6, -6), p + QPointF(6, 6));
    painter.drawLine(p + QPointF(-6, 6), p + QPointF(6, -6));
  };
  for (const auto& c : scene_.unreachable_frontiers) cross(c, QColor(220, 30, 30));
  for (const auto& c : scene_.blacklisted_frontiers) cross(c, QColor(20, 50, 150));
  if (scene_.path.size() > 1) {
    QPainterPath path(to_px(scene_.path.front().x(), scene_.path.front().y()));
    for (const auto& p : scene_.path) path.lineTo(to_px(p.x(), p.y()));
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(20, 170, 60), 2.5, Qt::DashLine));
    painter.drawPath(path);
  }
  if (scene_.has_goal) {
    const QPointF g = to_px(scene_.goal.x(), scene_.goal.y());
    painter.setPen(QPen(QColor(220, 30, 160), 2.5));
    painter.setBrush(Qt::NoBrush);
    painter.drawEllipse(g, 7.0, 7.0);
    painter.drawLine(g + QPointF(-10, 0), g + QPointF(10, 0));
    painter.drawLine(g + QPointF(0, -10), g + QPointF(0, 10));
  }
  // The robot: a disc of its footprint's order of size (at least visible) and its heading.
  const QPointF r = to_px(scene_.pose.x, scene_.pose.y);
  const double radius = std::max(5.0, 0.3 * px_per_m);
  painter.setPen(QPen(Qt::black, 1.5));
  painter.setBrush(QColor(255, 210, 0));
  painter.drawEllipse(r, radius, radius);
  painter.drawLine(r, r + QPointF(std::cos(scene_.pose.theta), -std::sin(scene_.pose.theta)) *
                              radius * 1.6);
}

}  // namespace dynamap::app::gui
