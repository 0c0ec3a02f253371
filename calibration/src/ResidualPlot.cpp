#include "dynamap/calibration/ResidualPlot.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "dynamap/robotio/AtomicFile.hpp"

namespace dynamap::calibration {
namespace {

constexpr double kDeg = M_PI / 180.0;
constexpr int kWidth = 900;
constexpr int kPanelHeight = 260;
constexpr int kMarginLeft = 80;
constexpr int kMarginTop = 40;
constexpr int kMarginBottom = 20;  // Room for the time axis label under the last panel.

const cv::Scalar kKinectColours[] = {{200, 90, 30}, {40, 140, 230}, {60, 170, 60}};
const cv::Scalar kInitialColour(190, 190, 190);
const cv::Scalar kLeftOutColour(30, 30, 220);

struct Series {
  std::vector<double> x, y;
  cv::Scalar colour;
  std::string label;
  // false: the series does not stretch the y axis; its points above the top are drawn on
  // the top edge as rings (pairs the solver left out can be metres off).
  bool scales_axis = true;
};

// One panel: axes, zero line, tick labels and the series as dots.
void DrawPanel(cv::Mat* image, int top, const std::string& y_label, const std::string& x_label,
               const std::vector<Series>& series) {
  const int left = kMarginLeft, right = kWidth - 20, bottom = top + kPanelHeight - 45;
  double x_min = 0.0, x_max = 1.0, y_max = 1e-9;
  bool first = true;
  for (const Series& s : series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      x_min = first ? s.x[i] : std::min(x_min, s.x[i]);
      x_max = first ? s.x[i] : std::max(x_max, s.x[i]);
      if (s.scales_axis) y_max = std::max(y_max, std::abs(s.y[i]));
      first = false;
    }
  }
  if (x_max <= x_min) x_max = x_min + 1.0;
  const cv::Scalar black(0, 0, 0), grid(225, 225, 225);
  cv::rectangle(*image, {left, top}, {right, bottom}, black, 1);
  auto px = [&](double x) { return left + static_cast<int>((x - x_min) / (x_max - x_min) * (right - left)); };
  auto py = [&](double y) { return bottom - static_cast<int>(y / (1.1 * y_max) * (bottom - top)); };
  for (int i = 1; i < 4; ++i) {
    const double y = 1.1 * y_max * i / 4.0;
    cv::line(*image, {left + 1, py(y)}, {right - 1, py(y)}, grid, 1);
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g", y);
    cv::putText(*image, text, {5, py(y) + 5}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1, cv::LINE_AA);
  }
  char range[64];
  std::snprintf(range, sizeof(range), "%.1f", x_min);
  cv::putText(*image, range, {left, bottom + 15}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1, cv::LINE_AA);
  std::snprintf(range, sizeof(range), "%.1f", x_max);
  cv::putText(*image, range, {right - 40, bottom + 15}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black, 1, cv::LINE_AA);
  cv::putText(*image, x_label, {(left + right) / 2 - 60, bottom + 30}, cv::FONT_HERSHEY_SIMPLEX,
              0.45, black, 1, cv::LINE_AA);
  cv::putText(*image, y_label, {left + 5, top - 6}, cv::FONT_HERSHEY_SIMPLEX, 0.5, black, 1, cv::LINE_AA);
  int legend_x = right - 10;
  for (auto it = series.rbegin(); it != series.rend(); ++it) {
    legend_x -= 12 + 8 * static_cast<int>(it->label.size());
    cv::circle(*image, {legend_x, top - 10}, 4, it->colour, cv::FILLED);
    cv::putText(*image, it->label, {legend_x + 8, top - 6}, cv::FONT_HERSHEY_SIMPLEX, 0.4, black,
                1, cv::LINE_AA);
  }
  for (const Series& s : series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      const double y = std::abs(s.y[i]);
      if (y > 1.1 * y_max) {
        cv::circle(*image, {px(s.x[i]), top + 4}, 4, s.colour, 1, cv::LINE_AA);
      } else {
        cv::circle(*image, {px(s.x[i]), py(y)}, 2, s.colour, cv::FILLED, cv::LINE_AA);
      }
    }
  }
}

robotio::Status WritePlot(const std::string& file, const std::string& title,
                          const std::string& x_label,
                          const std::vector<std::pair<std::string, std::vector<Series>>>& panels) {
  const int height = kMarginTop + static_cast<int>(panels.size()) * kPanelHeight + kMarginBottom;
  cv::Mat image(height, kWidth, CV_8UC3,
                cv::Scalar(255, 255, 255));
  cv::putText(image, title, {10, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.6, {0, 0, 0}, 1, cv::LINE_AA);
  for (std::size_t i = 0; i < panels.size(); ++i) {
    // The panels share the time axis: its label under the last one only (under the others
    // it ran into the next panel's legend).
    DrawPanel(&image, kMarginTop + 25 + static_cast<int>(i) * kPanelHeight, panels[i].first,
              i + 1 == panels.size() ? x_label : std::string(), panels[i].second);
  }
  std::vector<unsigned char> png;
  if (!cv::imencode(".png", image, png)) return robotio::Error{file + ": PNG encoding failed"};
  return robotio::WriteFileAtomically(file, std::string(png.begin(), png.end()));
}

}  // namespace

robotio::Expected<std::vector<std::string>> WriteResidualPlots(const SolverResult& result,
                                                               const CaptureData& capture,
                                                               const std::string& dir) {
  std::vector<std::string> written;
  const std::filesystem::path base(dir);
  const robotio::Rig rig = [&] {
    robotio::Rig guess;
    for (const KinectCapture& k : capture.kinects) guess.kinects.push_back(k.guess);
    return result.ToRig(guess);
  }();

  // Floor: each frame's plane against the calibrated mount.
  std::vector<Series> normal_series, distance_series;
  for (std::size_t k = 0; k < capture.kinects.size() && k < rig.kinects.size(); ++k) {
    Series n{{}, {}, kKinectColours[k % 3], capture.kinects[k].guess.id};
    Series d = n;
    const Eigen::Vector3d expected = FloorNormalInKinect(rig.kinects[k].T_base_kinect);
    int frame = 0;
    for (const PlaneFit& fit : capture.kinects[k].floor) {
      if (!fit.ok) continue;
      n.x.push_back(frame);
      n.y.push_back(std::acos(std::clamp(fit.normal.dot(expected), -1.0, 1.0)) / kDeg);
      d.x.push_back(frame++);
      d.y.push_back(1000.0 * (fit.distance_m - rig.kinects[k].T_base_kinect.translation().z()));
    }
    normal_series.push_back(n);
    distance_series.push_back(d);
  }
  const std::string floor_file = (base / "residuals_floor.png").string();
  const robotio::Status floor_status =
      WritePlot(floor_file, "Floor step: plane fit vs calibrated mount", "frame",
                {{"|normal error| (deg)", normal_series}, {"|height error| (mm)", distance_series}});
  if (!floor_status.ok()) return floor_status.error();
  written.push_back(floor_file);

  const std::pair<CaptureStep, const char*> steps[] = {{CaptureStep::kTurn, "turn"},
                                                       {CaptureStep::kStraight, "straight"},
                                                       {CaptureStep::kArcs, "arcs"}};
  for (const auto& [step, name] : steps) {
    std::vector<Series> rotation, translation;
    Series initial_rot{{}, {}, kInitialColour, "closed form"};
    Series initial_trans = initial_rot;
    for (const PairResidual& r : result.initial_residuals) {
      if (r.step != step || r.left_out) continue;
      initial_rot.x.push_back(r.t_s);
      initial_rot.y.push_back(r.rotation_deg);
      initial_trans.x.push_back(r.t_s);
      initial_trans.y.push_back(1000.0 * r.translation_m);
    }
    rotation.push_back(initial_rot);
    translation.push_back(initial_trans);
    Series left_out_rot{{}, {}, kLeftOutColour, "left out", false};
    Series left_out_trans = left_out_rot;
    for (const PairResidual& r : result.final_residuals) {
      if (r.step != step || !r.left_out) continue;
      left_out_rot.x.push_back(r.t_s);
      left_out_rot.y.push_back(r.rotation_deg);
      left_out_trans.x.push_back(r.t_s);
      left_out_trans.y.push_back(1000.0 * r.translation_m);
    }
    for (std::size_t k = 0; k < capture.kinects.size(); ++k) {
      Series rot{{}, {}, kKinectColours[k % 3], capture.kinects[k].guess.id + " refined"};
      Series trans = rot;
      for (const PairResidual& r : result.final_residuals) {
        if (r.step != step || r.kinect != static_cast<int>(k) || r.left_out) continue;
        rot.x.push_back(r.t_s);
        rot.y.push_back(r.rotation_deg);
        trans.x.push_back(r.t_s);
        trans.y.push_back(1000.0 * r.translation_m);
      }
      rotation.push_back(rot);
      translation.push_back(trans);
    }
    rotation.push_back(left_out_rot);
    translation.push_back(left_out_trans);
    const std::string file = (base / (std::string("residuals_") + name + ".png")).string();
    const robotio::Status status =
        WritePlot(file, std::string("Motion pairs while driving: ") + name +
                            " (ICP motion vs odometry through the rig)",
                  "time since start (s)",
                  {{"|rotation error| (deg)", rotation}, {"|translation error| (mm)", translation}});
    if (!status.ok()) return status.error();
    written.push_back(file);
  }
  return written;
}

}  // namespace dynamap::calibration
