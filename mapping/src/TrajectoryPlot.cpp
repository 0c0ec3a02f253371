#include "dynamap/mapping/TrajectoryPlot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "dynamap/robotio/AtomicFile.hpp"
#include "dynamap/robotio/Time.hpp"

namespace dynamap::mapping {
namespace {

constexpr int kWidth = 1000;
constexpr int kHeight = 420;
constexpr int kLeft = 70, kRight = kWidth - 20, kTop = 50, kBottom = kHeight - 50;
// Blue, orange, grey, green (BGR): the first estimate is the one the reader looks for.
const cv::Scalar kColours[] = {{200, 90, 30}, {40, 140, 230}, {150, 150, 150}, {60, 170, 60}};

void Text(cv::Mat* image, const std::string& text, cv::Point at, double scale = 0.45) {
  cv::putText(*image, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, {0, 0, 0}, 1, cv::LINE_AA);
}

std::string Format(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

}  // namespace

std::vector<std::pair<double, double>> PositionErrorOverTime(const robotio::Trajectory& ground_truth,
                                                             const robotio::Trajectory& estimate,
                                                             double max_stamp_difference_s) {
  std::vector<std::pair<double, double>> errors;
  if (ground_truth.empty()) return errors;
  const std::int64_t origin = ground_truth.front().stamp_ns;
  for (const auto& [g, e] : AssociateStamps(ground_truth, estimate, max_stamp_difference_s)) {
    errors.emplace_back(robotio::NanosToSeconds(ground_truth[g].stamp_ns - origin),
                        (ground_truth[g].pose.translation() - estimate[e].pose.translation()).norm());
  }
  return errors;
}

robotio::Status WriteTrajectoryErrorPlot(const std::string& file,
                                         const robotio::Trajectory& ground_truth,
                                         const std::vector<PlottedTrajectory>& estimates) {
  struct Line {
    std::string label;
    std::vector<std::pair<double, double>> errors;
  };
  std::vector<Line> lines;
  double t_max = 1e-9, e_max = 1e-9;
  for (const PlottedTrajectory& estimate : estimates) {
    auto errors = PositionErrorOverTime(ground_truth, estimate.poses);
    if (errors.empty()) continue;
    double sum = 0.0;
    for (const auto& [t, e] : errors) {
      t_max = std::max(t_max, t);
      e_max = std::max(e_max, e);
      sum += e * e;
    }
    const double ate = std::sqrt(sum / static_cast<double>(errors.size()));
    lines.push_back({estimate.label + Format(" (ATE %.3f m)", ate), std::move(errors)});
  }
  if (lines.empty()) {
    return robotio::Error{file + ": no estimated pose matches a ground-truth stamp; nothing to plot"};
  }
  cv::Mat image(kHeight, kWidth, CV_8UC3, cv::Scalar(255, 255, 255));
  // Grid lines at a round step (1, 2 or 5 × 10ⁿ m), four to ten of them.
  const double magnitude = std::pow(10.0, std::floor(std::log10(e_max / 4.0)));
  double step = magnitude;
  for (double factor : {1.0, 2.0, 5.0, 10.0}) {
    step = factor * magnitude;
    if (e_max / step <= 10.0) break;
  }
  const double e_top = std::max(1.05 * e_max, step);
  auto px = [&](double t) { return kLeft + static_cast<int>(t / t_max * (kRight - kLeft)); };
  auto py = [&](double e) { return kBottom - static_cast<int>(e / e_top * (kBottom - kTop)); };
  for (double e = step; e <= e_top; e += step) {
    cv::line(image, {kLeft + 1, py(e)}, {kRight - 1, py(e)}, {225, 225, 225}, 1);
    const int decimals = std::max(0, static_cast<int>(std::ceil(-std::log10(step) - 1e-9)));
    char label[32];
    std::snprintf(label, sizeof(label), "%.*f", decimals, e);
    Text(&image, label, {8, py(e) + 5}, 0.4);
  }
  for (int i = 0; i <= 5; ++i) {
    const double t = t_max * i / 5.0;
    Text(&image, Format(t_max < 10.0 ? "%.1f" : "%.0f", t), {px(t) - 10, kBottom + 18}, 0.4);
  }
  cv::rectangle(image, {kLeft, kTop}, {kRight, kBottom}, {0, 0, 0}, 1);
  Text(&image, "time since the first ground-truth pose (s)", {kWidth / 2 - 150, kBottom + 40});
  Text(&image, "position error (m)", {kLeft, kTop - 28});
  // The last first, so the first estimate's line is drawn on top.
  for (std::size_t k = lines.size(); k-- > 0;) {
    const cv::Scalar& colour = kColours[k % std::size(kColours)];
    const auto& errors = lines[k].errors;
    for (std::size_t i = 1; i < errors.size(); ++i) {
      cv::line(image, {px(errors[i - 1].first), py(errors[i - 1].second)},
               {px(errors[i].first), py(errors[i].second)}, colour, 2, cv::LINE_AA);
    }
  }
  int legend_x = kLeft + 170;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const cv::Scalar& colour = kColours[k % std::size(kColours)];
    cv::line(image, {legend_x, kTop - 32}, {legend_x + 20, kTop - 32}, colour, 3);
    Text(&image, lines[k].label, {legend_x + 25, kTop - 28});
    legend_x += 40 + 8 * static_cast<int>(lines[k].label.size());
  }
  return robotio::WriteFileAtomically(file, [&](const std::string& temporary) {
    return cv::imwrite(temporary, image, {cv::IMWRITE_PNG_COMPRESSION, 6});
  });
}

}  // namespace dynamap::mapping
