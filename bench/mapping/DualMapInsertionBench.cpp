// Scans per second of stock octomap::OcTree::insertPointCloud (discretize on) and of the
// dual map's batched update on the same recorded frames (both Kinects, ground-truth poses),
// in one run, and the time to turn a depth frame into rays.
// Usage: bench_dual_map --log DIR [--frames N] [--resolution M] [--max-range M] [--rounds N]
#include <octomap/OcTree.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Pose2D.hpp"
#include "dynamap/robotio/RecordingReader.hpp"

namespace {

using dynamap::robotio::PointList;

struct Frame {
  PointList points_map;        // Valid points of the frame in the map frame.
  Eigen::Vector3f origin_map;  // Kinect centre in the map frame.
  dynamap::robotio::DepthFrame depth;
  Eigen::Isometry3d T_map_base = Eigen::Isometry3d::Identity();
};

Eigen::Isometry3d PoseAt(const dynamap::robotio::Trajectory& trajectory, std::int64_t stamp) {
  std::size_t i = 0;
  while (i + 1 < trajectory.size() && trajectory[i + 1].stamp_ns <= stamp) ++i;
  return trajectory[i].pose;
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
  std::string log;
  std::size_t max_frames = 200;
  double resolution = 0.05, max_range = 4.0;
  int rounds = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--log") log = argv[i + 1];
    if (key == "--frames") max_frames = std::strtoul(argv[i + 1], nullptr, 10);
    if (key == "--resolution") resolution = std::strtod(argv[i + 1], nullptr);
    if (key == "--max-range") max_range = std::strtod(argv[i + 1], nullptr);
    if (key == "--rounds") rounds = std::max(1, std::atoi(argv[i + 1]));
  }
  if (log.empty()) {
    std::fprintf(stderr, "usage: bench_dual_map --log RECORDING [--frames N] [--resolution M] "
                         "[--max-range M] [--rounds N]\n");
    return 2;
  }
  auto reader = dynamap::robotio::RecordingReader::Open(log);
  if (!reader) {
    std::fprintf(stderr, "bench_dual_map: %s\n", reader.error().message.c_str());
    return 2;
  }
  if (reader->ground_truth().empty()) {
    std::fprintf(stderr, "bench_dual_map: %s has no groundtruth.txt\n", log.c_str());
    return 2;
  }
  std::vector<Frame> frames;
  std::size_t points = 0;
  for (const auto& entry : reader->depth_entries()) {
    if (frames.size() >= max_frames) break;
    auto depth = reader->LoadDepth(entry);
    if (!depth || depth->sensor_id >= static_cast<int>(reader->rig().kinects.size())) continue;
    const auto& mount = reader->rig().kinects[static_cast<std::size_t>(depth->sensor_id)];
    const Eigen::Isometry3f T =
        (PoseAt(reader->ground_truth(), depth->stamp_ns) * mount.T_base_kinect).cast<float>();
    Frame frame;
    frame.origin_map = T.translation();
    // Every valid return up to the sensor's own limit; both inserters cut at max_range.
    for (const Eigen::Vector3f& p : dynamap::robotio::DepthToPoints(*depth, mount.min_range_m, 1e3)) {
      frame.points_map.push_back(T * p);
    }
    points += frame.points_map.size();
    frame.T_map_base = PoseAt(reader->ground_truth(), depth->stamp_ns);
    frame.depth = std::move(*depth);
    frames.push_back(std::move(frame));
  }
  if (frames.empty()) {
    std::fprintf(stderr, "bench_dual_map: no frames in %s\n", log.c_str());
    return 2;
  }

  std::vector<octomap::Pointcloud> clouds(frames.size());
  for (std::size_t i = 0; i < frames.size(); ++i) {
    clouds[i].reserve(frames[i].points_map.size());
    for (const auto& p : frames[i].points_map) clouds[i].push_back(p.x(), p.y(), p.z());
  }
  // Stock OctoMap, the dual map on one thread (as stock OctoMap runs) and with its default
  // threads (MappingConfig::insert_threads), in turn for `rounds` rounds: this machine's
  // speed wanders by a quarter from minute to minute, so each figure is the median round.
  // The two dual maps must be the same.
  dynamap::mapping::MappingConfig config;
  config.resolution_m = resolution;
  config.max_range_m = max_range;
  const int default_threads = config.insert_threads;
  std::vector<double> stock_runs, dual_runs[2];  // Dual: one thread, default threads.
  std::size_t stock_nodes = 0, dual_nodes[2] = {0, 0};
  for (int round = 0; round < rounds; ++round) {
    octomap::OcTree stock(resolution);
    auto start = std::chrono::steady_clock::now();
    for (std::size_t i = 0; i < frames.size(); ++i) {
      const auto& o = frames[i].origin_map;
      stock.insertPointCloud(clouds[i], octomap::point3d(o.x(), o.y(), o.z()), max_range,
                             /*lazy_eval=*/false, /*discretize=*/true);
    }
    stock_runs.push_back(SecondsSince(start));
    stock_nodes = stock.size();
    for (int run = 0; run < 2; ++run) {
      config.insert_threads = run == 0 ? 1 : default_threads;
      dynamap::mapping::DualMap dual(config);
      start = std::chrono::steady_clock::now();
      for (const Frame& frame : frames) dual.InsertPointCloud(frame.points_map, frame.origin_map);
      dual_runs[run].push_back(SecondsSince(start));
      dual_nodes[run] = dual.tree().size();
    }
  }
  const double stock_s = Median(stock_runs);
  const double dual_s[2] = {Median(dual_runs[0]), Median(dual_runs[1])};

  // Depth frames to rays as the map inserts them (DualMap::RaysOf): without the edge
  // clearance, with it but without filling grazing gaps, and with the defaults.
  const dynamap::mapping::MappingConfig defaults;
  dynamap::mapping::MappingConfig ray_configs[3] = {config, config, config};
  ray_configs[0].edge_clearance_voxels = 0.0;
  ray_configs[1].edge_clearance_voxels = defaults.edge_clearance_voxels;
  ray_configs[1].grazing_gap_deg = 0.0;
  ray_configs[2].edge_clearance_voxels = defaults.edge_clearance_voxels;
  ray_configs[2].grazing_gap_deg = defaults.grazing_gap_deg;
  double rays_s[3] = {0.0, 0.0, 0.0};
  std::size_t checksum = 0;
  for (int variant = 0; variant < 3; ++variant) {
    const dynamap::mapping::DualMap ray_map(ray_configs[variant]);
    const auto start = std::chrono::steady_clock::now();
    for (const Frame& frame : frames) {
      const auto& mount = reader->rig().kinects[static_cast<std::size_t>(frame.depth.sensor_id)];
      checksum += ray_map.RaysOf(frame.depth, mount, frame.T_map_base).ends.size();
    }
    rays_s[variant] = SecondsSince(start);
  }

  const double n = static_cast<double>(frames.size());
  std::printf("frames (scans)         %zu (avg %.0f points)\n", frames.size(),
              static_cast<double>(points) / n);
  std::printf("resolution / range     %.3f m / %.1f m\n", resolution, max_range);
  std::printf("rounds                 %d (median shown)\n", rounds);
  std::printf("stock OcTree           %.1f scans/s (%.2f ms/scan, %zu nodes)\n", n / stock_s,
              1e3 * stock_s / n, stock_nodes);
  std::printf("dual map, 1 thread     %.1f scans/s (%.2f ms/scan, %zu nodes)\n", n / dual_s[0],
              1e3 * dual_s[0] / n, dual_nodes[0]);
  std::printf("dual map, %d threads    %.1f scans/s (%.2f ms/scan, %zu nodes%s)\n", default_threads,
              n / dual_s[1], 1e3 * dual_s[1] / n, dual_nodes[1],
              dual_nodes[1] == dual_nodes[0] ? "" : ", NOT the one-thread map");
  std::printf("ratio dual / stock     %.2fx (1 thread %.2fx)\n", stock_s / dual_s[1],
              stock_s / dual_s[0]);
  std::printf("depth to rays          %.2f ms/frame; with edge clearance %.2f, with grazing gaps "
              "filled too (the default) %.2f ms/frame (%zu rays)\n",
              1e3 * rays_s[0] / n, 1e3 * rays_s[1] / n, 1e3 * rays_s[2] / n, checksum / 3);
  return 0;
}
