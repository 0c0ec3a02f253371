#include "dynamap/app/runtime/MissionOutputs.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "dynamap/robotio/AtomicFile.hpp"

namespace dynamap::app::runtime {

namespace {

using planning::CellState;

// Image row of grid row y: the map's y axis points up, images count rows down.
cv::Point Pixel(const planning::GridMap& grid, double x, double y) {
  const planning::GridIndex c = grid.CellAt(x, y);
  return {c.x, grid.height - 1 - c.y};
}

void DrawPath(cv::Mat& image, const planning::GridMap& grid,
              const std::vector<robotio::Pose2D>& path, const cv::Scalar& colour) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    cv::line(image, Pixel(grid, path[i - 1].x, path[i - 1].y), Pixel(grid, path[i].x, path[i].y),
             colour, 1, cv::LINE_AA);
  }
}

// The projected map faded to a background: free light, unknown mid, the rest darker.
cv::Mat FadedGrid(const planning::GridMap& grid) {
  cv::Mat image(grid.height, grid.width, CV_8UC3);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const CellState state = grid.At({x, y});
      const std::uint8_t v = state == CellState::kNavigable ? 250
                             : state == CellState::kUnknown ? 215
                                                            : 175;
      image.at<cv::Vec3b>(grid.height - 1 - y, x) = {v, v, v};
    }
  }
  return image;
}

// Saved at 2 px per cell with a 1 m scale bar and a caption beside it.
robotio::Status WriteEnlargedWithScaleBar(const cv::Mat& image, const planning::GridMap& grid,
                                          const std::string& caption, const std::string& file) {
  constexpr int kScale = 2;
  cv::Mat big;
  cv::resize(image, big, cv::Size(), kScale, kScale, cv::INTER_NEAREST);
  const int metre = static_cast<int>(kScale / grid.resolution_m);
  cv::line(big, {10, big.rows - 12}, {10 + metre, big.rows - 12}, cv::Scalar(0, 0, 0), 3);
  cv::putText(big, "1 m   " + caption, {14 + metre, big.rows - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  return robotio::WriteFileAtomically(file, [&big](const std::string& path) {
    return cv::imwrite(path, big);
  });
}

// [[x, y], ...] rounded to the millimetre.
nlohmann::json Points(const std::vector<Eigen::Vector2d>& points) {
  nlohmann::json list = nlohmann::json::array();
  for (const Eigen::Vector2d& p : points) {
    list.push_back({std::round(p.x() * 1e3) / 1e3, std::round(p.y() * 1e3) / 1e3});
  }
  return list;
}

}  // namespace

robotio::Status WriteMapPicture(const planning::GridMap& grid,
                                const std::vector<robotio::Pose2D>& estimated,
                                const std::vector<robotio::Pose2D>& truth,
                                const PlannerMarks& marks, const std::string& file) {
  cv::Mat image(grid.height, grid.width, CV_8UC3);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      cv::Vec3b colour;
      switch (grid.At({x, y})) {
        case CellState::kNavigable: colour = {255, 255, 255}; break;
        case CellState::kObstacle: colour = {40, 40, 40}; break;
        case CellState::kHole: colour = {200, 120, 30}; break;
        case CellState::kUnknown: colour = {170, 170, 170}; break;
      }
      image.at<cv::Vec3b>(grid.height - 1 - y, x) = colour;
    }
  }
  // Draw at 2x so paths and markers stay readable.
  cv::Mat big;
  cv::resize(image, big, cv::Size(), 2.0, 2.0, cv::INTER_NEAREST);
  const planning::GridMap scaled = [&] {
    planning::GridMap g;
    g.width = grid.width * 2;
    g.height = grid.height * 2;
    g.resolution_m = grid.resolution_m / 2.0;
    g.origin_x_m = grid.origin_x_m;
    g.origin_y_m = grid.origin_y_m;
    return g;
  }();
  DrawPath(big, scaled, truth, cv::Scalar(60, 170, 60));
  DrawPath(big, scaled, estimated, cv::Scalar(0, 140, 255));
  for (const auto& t : marks.targets) {
    cv::drawMarker(big, Pixel(scaled, t.x(), t.y()), cv::Scalar(200, 0, 200), cv::MARKER_DIAMOND,
                   10, 2);
  }
  for (const auto& t : marks.unreachable_frontiers) {
    cv::drawMarker(big, Pixel(scaled, t.x(), t.y()), cv::Scalar(0, 0, 220),
                   cv::MARKER_TILTED_CROSS, 14, 2);
  }
  for (const auto& t : marks.blacklisted_frontiers) {
    cv::drawMarker(big, Pixel(scaled, t.x(), t.y()), cv::Scalar(140, 40, 0),
                   cv::MARKER_TILTED_CROSS, 14, 2);
  }
  cv::circle(big, Pixel(scaled, 0.0, 0.0), 6, cv::Scalar(0, 0, 220), 2, cv::LINE_AA);
  // Scale bar: 1 m.
  const int metre = static_cast<int>(1.0 / scaled.resolution_m);
  cv::line(big, {10, big.rows - 12}, {10 + metre, big.rows - 12}, cv::Scalar(0, 0, 0), 3);
  cv::putText(big, "1 m", {14 + metre, big.rows - 8}, cv::FONT_HERSHEY_SIMPLEX, 0.45,
              cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  return robotio::WriteFileAtomically(file, [&big](const std::string& path) {
    return cv::imwrite(path, big);
  });
}

robotio::Status WriteCoveragePicture(const planning::GridMap& grid,
                                     const SurfaceCoverageResult& coverage,
                                     const std::string& file) {
  cv::Mat image = FadedGrid(grid);
  // Per cell: samples inspected and visible.
  std::vector<std::pair<int, int>> counts(grid.cells.size(), {0, 0});
  const auto add = [&](const robotio::PointList& samples, bool seen) {
    for (const Eigen::Vector3f& p : samples) {
      const planning::GridIndex c = grid.CellAt(p.x(), p.y());
      if (!grid.Contains(c)) continue;
      auto& [inspected, visible] = counts[static_cast<std::size_t>(grid.Index(c))];
      inspected += seen ? 1 : 0;
      ++visible;
    }
  };
  add(coverage.inspected, true);
  add(coverage.missed, false);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const auto [inspected, visible] = counts[static_cast<std::size_t>(grid.Index({x, y}))];
      if (visible == 0) continue;
      const double share = static_cast<double>(inspected) / visible;
      image.at<cv::Vec3b>(grid.height - 1 - y, x) = {
          40, static_cast<std::uint8_t>(60 + 140 * share),
          static_cast<std::uint8_t>(220 - 180 * share)};  // BGR: red → green.
    }
  }
  return WriteEnlargedWithScaleBar(
      image, grid,
      "surfaces seen closely: " +
          std::to_string(static_cast<int>(100.0 * coverage.Fraction() + 0.5)) +
          " % (green), missed red",
      file);
}

robotio::Status WriteAccuracyPicture(const planning::GridMap& grid,
                                     const mapping::MisclassifiedVoxels& misclassified,
                                     const mapping::PointAccuracy& accuracy,
                                     const std::string& file) {
  cv::Mat image = FadedGrid(grid);
  // Per cell: labelled points the final static map got wrong, over all heights.
  std::vector<std::uint64_t> lost(grid.cells.size(), 0), kept(grid.cells.size(), 0);
  const auto add = [&](const robotio::PointList& voxels, const std::vector<std::uint64_t>& points,
                       std::vector<std::uint64_t>& per_cell) {
    for (std::size_t i = 0; i < voxels.size(); ++i) {
      const planning::GridIndex c = grid.CellAt(voxels[i].x(), voxels[i].y());
      if (grid.Contains(c)) per_cell[static_cast<std::size_t>(grid.Index(c))] += points[i];
    }
  };
  add(misclassified.static_lost, misclassified.static_lost_points, lost);
  add(misclassified.dynamic_kept, misclassified.dynamic_kept_points, kept);
  // Colour strength grows with the logarithm of the count, full in the worst cell of each
  // kind: one stray point shows faintly, the place that lost the most stands out.
  const auto strength = [](std::uint64_t n, std::uint64_t most) {
    return most == 0 ? 0.0 : std::log1p(static_cast<double>(n)) / std::log1p(static_cast<double>(most));
  };
  const auto most = [](const std::vector<std::uint64_t>& per_cell) {
    return per_cell.empty() ? std::uint64_t{0} : *std::max_element(per_cell.begin(), per_cell.end());
  };
  const std::uint64_t most_lost = most(lost), most_kept = most(kept);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      const auto cell = static_cast<std::size_t>(grid.Index({x, y}));
      if (lost[cell] == 0 && kept[cell] == 0) continue;
      const double b = 0.4 + 0.6 * strength(lost[cell], most_lost);
      const double r = 0.4 + 0.6 * strength(kept[cell], most_kept);
      image.at<cv::Vec3b>(grid.height - 1 - y, x) = {
          static_cast<std::uint8_t>(lost[cell] > 0 ? 255 * b : 40), 40,
          static_cast<std::uint8_t>(kept[cell] > 0 ? 255 * r : 40)};
    }
  }
  char caption[160];
  std::snprintf(caption, sizeof caption,
                "static points lost (blue): SA %.3f   dynamic points kept (red): DA %.3f",
                accuracy.static_accuracy, accuracy.dynamic_accuracy);
  return WriteEnlargedWithScaleBar(image, grid, caption, file);
}

robotio::Status WriteRosMap(const planning::GridMap& grid, const std::string& pgm,
                            const std::string& yaml) {
  cv::Mat image(grid.height, grid.width, CV_8UC1);
  for (int y = 0; y < grid.height; ++y) {
    for (int x = 0; x < grid.width; ++x) {
      std::uint8_t v = 205;
      const CellState s = grid.At({x, y});
      if (s == CellState::kNavigable) v = 254;
      if (s == CellState::kObstacle || s == CellState::kHole) v = 0;
      image.at<std::uint8_t>(grid.height - 1 - y, x) = v;
    }
  }
  if (auto status = robotio::WriteFileAtomically(
          pgm, [&image](const std::string& path) { return cv::imwrite(path, image); });
      !status) {
    return status;
  }
  char text[512];
  std::snprintf(text, sizeof(text),
                "image: %s\nresolution: %.6f\norigin: [%.6f, %.6f, 0.0]\nnegate: 0\n"
                "occupied_thresh: 0.65\nfree_thresh: 0.196\n",
                std::filesystem::path(pgm).filename().c_str(), grid.resolution_m,
                grid.origin_x_m, grid.origin_y_m);
  return robotio::WriteFileAtomically(yaml, std::string(text));
}

robotio::Status WriteReportJson(const MissionReport& r, const std::string& extra_json_fields,
                                const std::string& file) {
  nlohmann::json j = {
      {"completed", r.completed},
      {"explored_free_fraction", r.explored_free_fraction},
      {"surface_coverage", r.surface_coverage},
      {"path_length_m", r.path_length_m},
      {"mission_time_s", r.mission_time_s},
      {"collisions", r.collisions},
      {"ate_rmse_m", r.ate_rmse_m},
      {"ate_rmse_m_online", r.online_ate_rmse_m},
      {"odometry_ate_rmse_m", r.odometry_ate_rmse_m},
      {"static_accuracy", r.static_accuracy},
      {"dynamic_accuracy", r.dynamic_accuracy},
      {"associated_accuracy", r.associated_accuracy},
      {"dynamic_accuracy_above_floor", r.dynamic_accuracy_above_floor},
      {"static_accuracy_above_floor", r.static_accuracy_above_floor},
      {"frames_delivered", r.frames_delivered},
      {"frames_dropped", r.frames_dropped},
      {"frames_processed", r.frames_processed},
      {"registrations_accepted", r.registrations_accepted},
      {"registrations_rejected", r.registrations_rejected},
      {"loop_closures", r.loop_closures},
      {"guard_stops", r.guard_stops},
      {"map_guard_stops", r.map_guard_stops},
      {"map_guard_give_ups", r.map_guard_give_ups},
      {"stall_stops", r.stall_stops},
      {"path_shifted_s", r.path_shifted_s},
      {"path_shift_max_m", r.path_shift_max_m},
      {"plans", r.plans},
      {"unreachable_targets", r.unreachable_targets},
      {"blocked_plans", r.blocked_plans},
      {"squeezed_plans", r.squeezed_plans},
      {"last_try_regions", r.last_try_regions},
      {"frontiers_left", {{"unreachable", Points(r.unreachable_frontiers)},
                          {"blacklisted", Points(r.blacklisted_frontiers)}}},
      {"planner_median_ms", r.plan_median_ms},
      {"planner_p95_ms", r.plan_p95_ms},
      {"map_insert_median_ms", r.insert_median_ms},
      {"map_insert_p95_ms", r.insert_p95_ms},
      {"wall_time_s", r.wall_time_s},
      {"simulated_s_per_wall_s", r.wall_time_s > 0.0 ? r.mission_time_s / r.wall_time_s : 0.0},
      {"cpu_s",
       {{"simulation", r.cpu.simulation_s},
        {"mapping", r.cpu.mapping_s},
        {"planning", r.cpu.planning_s},
        {"control", r.cpu.control_s},
        {"other", r.cpu.other_s}}},
      {"files", r.files},
  };
  if (!extra_json_fields.empty()) j.update(nlohmann::json::parse(extra_json_fields));
  return robotio::WriteFileAtomically(file, j.dump(2) + "\n");
}

}  // namespace dynamap::app::runtime
