#include "dynamap/app/gui/DepthPreview.hpp"

#include <QPainter>
#include <algorithm>
#include <array>
#include <cmath>

namespace dynamap::app::gui {

namespace {

// A perceptual ramp from near (yellow) over orange and magenta to far (dark blue).
QRgb RampColour(double s) {
  constexpr std::array<std::array<double, 3>, 5> kStops = {{{252, 253, 191},
                                                            {253, 150, 60},
                                                            {222, 73, 104},
                                                            {130, 38, 129},
                                                            {28, 16, 68}}};
  s = std::clamp(s, 0.0, 1.0) * (kStops.size() - 1);
  const auto k = std::min<std::size_t>(static_cast<std::size_t>(s), kStops.size() - 2);
  const double f = s - static_cast<double>(k);
  const auto mix = [&](int c) {
    return static_cast<int>(kStops[k][c] + f * (kStops[k + 1][c] - kStops[k][c]));
  };
  return qRgb(mix(0), mix(1), mix(2));
}

}  // namespace

QImage DepthToImage(const robotio::DepthFrame& frame, const DepthImageOptions& options) {
  if (!frame.Valid()) return QImage();
  QImage image(frame.width, frame.height, QImage::Format_RGB32);
  const auto& k = frame.intrinsics;
  for (int v = 0; v < frame.height; ++v) {
    auto* row = reinterpret_cast<QRgb*>(image.scanLine(v));
    for (int u = 0; u < frame.width; ++u) {
      const std::uint16_t mm = frame.At(u, v);
      if (mm == 0) {
        row[u] = qRgb(0, 0, 0);
        continue;
      }
      const double z = mm / 1000.0;
      QRgb colour = RampColour(z / options.max_range_m);
      if (options.plane) {
        const Eigen::Vector3d p((u - k.cx) / k.fx * z, (v - k.cy) / k.fy * z, z);
        if (std::abs(options.plane->normal.dot(p) + options.plane->distance_m) <
            options.plane->band_m) {
          colour = qRgb((qRed(colour) + 40) / 3, (qGreen(colour) + 2 * 230) / 3,
                        (qBlue(colour) + 60) / 3);
        }
      }
      row[u] = colour;
    }
  }
  return options.rotate_180 ? image.mirrored(true, true) : image;
}

DepthPreview::DepthPreview(const QString& title, QWidget* parent)
    : QWidget(parent), title_(title) {
  setMinimumSize(160, 130);
}

void DepthPreview::SetFrame(const robotio::DepthFrame& frame, const DepthImageOptions& options) {
  image_ = DepthToImage(frame, options);
  caption_ = tr("%1  %2×%3  t %4 s")
                 .arg(title_)
                 .arg(frame.width)
                 .arg(frame.height)
                 .arg(frame.stamp_ns / 1e9, 0, 'f', 1);
  update();
}

void DepthPreview::Clear() {
  image_ = QImage();
  caption_.clear();
  update();
}

void DepthPreview::paintEvent(QPaintEvent*) {
  QPainter painter(this);
  painter.fillRect(rect(), QColor(24, 25, 29));
  const int caption_height = fontMetrics().height() + 4;
  const QRect area = rect().adjusted(2, caption_height, -2, -2);
  painter.setPen(QColor(220, 220, 220));
  painter.drawText(rect().adjusted(4, 2, -4, 0), Qt::AlignLeft | Qt::AlignTop,
                   caption_.isEmpty() ? title_ + tr("  (no frame yet)") : caption_);
  if (image_.isNull()) return;
  const QSize size = image_.size().scaled(area.size(), Qt::KeepAspectRatio);
  const QRect target(area.x() + (area.width() - size.width()) / 2,
                     area.y() + (area.height() - size.height()) / 2, size.width(),
                     size.height());
  painter.setRenderHint(QPainter::SmoothPixmapTransform);
  painter.drawImage(target, image_);
}

}  // namespace dynamap::app::gui
