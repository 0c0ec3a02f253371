#include "dynamap/mapping/MapEvaluation.hpp"

#include <cmath>
#include <cstdio>

#include "dynamap/mapping/MapExport.hpp"

namespace dynamap::mapping {
namespace {

double Ratio(std::uint64_t part, std::uint64_t whole, double if_empty) {
  return whole == 0 ? if_empty : static_cast<double>(part) / static_cast<double>(whole);
}

template <typename F>
bool AnyNeighbour(const octomap::OcTreeKey& key, F&& f) {
  for (int dx = -1; dx <= 1; ++dx) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dz = -1; dz <= 1; ++dz) {
        const octomap::OcTreeKey n(static_cast<octomap::key_type>(key[0] + dx),
                                   static_cast<octomap::key_type>(key[1] + dy),
                                   static_cast<octomap::key_type>(key[2] + dz));
        if (f(n)) return true;
      }
    }
  }
  return false;
}

// A labelled point is kept when its voxel is occupied in the final static map.
bool KeptInStaticMap(const DualOcTree& final_map, const octomap::point3d& centre) {
  const DualOcTreeNode* node = final_map.search(centre);
  return node != nullptr && final_map.IsStaticOccupied(*node);
}

}  // namespace

PointAccuracyCounter::PointAccuracyCounter(double resolution_m, double max_range_m, int stride)
    : max_range_m_(max_range_m),
      stride_(std::max(stride, 1)),
      key_frame_(resolution_m) {}

void PointAccuracyCounter::Add(const robotio::DepthFrame& depth,
                               const robotio::LabelFrame& labels,
                               const robotio::KinectMount& mount,
                               const Eigen::Isometry3d& T_map_base) {
  if (labels.width != depth.width || labels.height != depth.height) return;
  const Eigen::Isometry3f T = (T_map_base * mount.T_base_kinect).cast<float>();
  const robotio::Intrinsics& k = depth.intrinsics;
  const double min_mm = mount.min_range_m * 1000.0;
  const double max_mm = std::min(mount.max_range_m, max_range_m_) * 1000.0;
  for (int v = 0; v < depth.height; v += stride_) {
    for (int u = 0; u < depth.width; u += stride_) {
      const std::size_t index = static_cast<std::size_t>(v) * depth.width + u;
      const std::uint16_t label = labels.labels[index];
      const std::uint16_t d = depth.depth_mm[index];
      if (label == 0 || d == 0 || d < min_mm) continue;
      const float z = static_cast<float>(d) * 0.001f;
      const Eigen::Vector3f ray(static_cast<float>((u - k.cx) / k.fx), static_cast<float>((v - k.cy) / k.fy), 1.0f);
      // The map's range limit is a depth, as in DepthToRays.
      if (d > max_mm) continue;
      const Eigen::Vector3f p = T * (ray * z);
      octomap::OcTreeKey key;
      if (!key_frame_.coordToKeyChecked(octomap::point3d(p.x(), p.y(), p.z()), key)) continue;
      Counts& c = counts_[key];
      ++(robotio::LabelFrame::IsDynamic(label) ? c.dynamic_points : c.static_points);
    }
  }
}

PointAccuracy PointAccuracyCounter::Evaluate(const DualOcTree& final_map) const {
  PointAccuracy result;
  for (const auto& [key, counts] : counts_) {
    const octomap::point3d centre = key_frame_.keyToCoord(key);
    const bool kept = KeptInStaticMap(final_map, centre);
    result.static_points += counts.static_points;
    result.dynamic_points += counts.dynamic_points;
    if (kept) result.static_kept += counts.static_points;
    if (!kept) result.dynamic_removed += counts.dynamic_points;
    if (centre.z() < 2.0 * key_frame_.getResolution()) {
      result.dynamic_points_near_floor += counts.dynamic_points;
      result.static_points_near_floor += counts.static_points;
      if (kept) {
        result.dynamic_kept_near_floor += counts.dynamic_points;
        result.static_kept_near_floor += counts.static_points;
      }
    }
  }
  const std::uint64_t above_floor = result.dynamic_points - result.dynamic_points_near_floor;
  const std::uint64_t removed_above_floor = result.dynamic_removed -
      (result.dynamic_points_near_floor - result.dynamic_kept_near_floor);
  result.dynamic_accuracy_above_floor = Ratio(removed_above_floor, above_floor, 1.0);
  result.static_accuracy_above_floor =
      Ratio(result.static_kept - result.static_kept_near_floor,
            result.static_points - result.static_points_near_floor, 1.0);
  result.static_accuracy = Ratio(result.static_kept, result.static_points, 1.0);
  result.dynamic_accuracy = Ratio(result.dynamic_removed, result.dynamic_points, 1.0);
  result.associated_accuracy = std::sqrt(result.static_accuracy * result.dynamic_accuracy);
  return result;
}

MisclassifiedVoxels PointAccuracyCounter::Misclassified(const DualOcTree& final_map) const {
  MisclassifiedVoxels result;
  for (const auto& [key, counts] : counts_) {
    const octomap::point3d c = key_frame_.keyToCoord(key);
    const bool kept = KeptInStaticMap(final_map, c);
    const Eigen::Vector3f centre(c.x(), c.y(), c.z());
    if (!kept && counts.static_points > 0) {
      result.static_lost.push_back(centre);
      result.static_lost_points.push_back(counts.static_points);
    }
    if (kept && counts.dynamic_points > 0) {
      result.dynamic_kept.push_back(centre);
      result.dynamic_kept_points.push_back(counts.dynamic_points);
    }
  }
  return result;
}

std::string MisclassifiedVoxelsCsv(const MisclassifiedVoxels& misclassified) {
  std::string text =
      "# voxel centre (m, map frame), labelled points the final static map got wrong\n"
      "x,y,z,static_points_lost,dynamic_points_kept\n";
  char line[96];
  const auto add = [&](const robotio::PointList& voxels, const std::vector<std::uint64_t>& points,
                       bool static_lost) {
    for (std::size_t i = 0; i < voxels.size(); ++i) {
      std::snprintf(line, sizeof line, "%.3f,%.3f,%.3f,%llu,%llu\n", voxels[i].x(), voxels[i].y(),
                    voxels[i].z(), static_cast<unsigned long long>(static_lost ? points[i] : 0),
                    static_cast<unsigned long long>(static_lost ? 0 : points[i]));
      text += line;
    }
  };
  add(misclassified.static_lost, misclassified.static_lost_points, true);
  add(misclassified.dynamic_kept, misclassified.dynamic_kept_points, false);
  return text;
}

SurfaceAccuracy EvaluateStaticSurfaces(const DualOcTree& map,
                                       const robotio::PointList& surface_samples) {
  SurfaceAccuracy result;
  octomap::KeySet sample_keys;
  for (const Eigen::Vector3f& p : surface_samples) {
    octomap::OcTreeKey key;
    if (map.coordToKeyChecked(octomap::point3d(p.x(), p.y(), p.z()), key)) sample_keys.insert(key);
  }
  octomap::KeySet occupied_keys;
  for (const Eigen::Vector3f& c : OccupiedVoxelCentres(map, MapChannel::kStatic)) {
    occupied_keys.insert(map.coordToKey(octomap::point3d(c.x(), c.y(), c.z())));
  }
  result.occupied_voxels = occupied_keys.size();
  for (const octomap::OcTreeKey& key : occupied_keys) {
    if (AnyNeighbour(key, [&](const octomap::OcTreeKey& n) { return sample_keys.count(n) > 0; })) {
      ++result.precise_voxels;
    }
  }
  for (const octomap::OcTreeKey& key : sample_keys) {
    const bool observed = AnyNeighbour(
        key, [&](const octomap::OcTreeKey& n) { return map.search(n) != nullptr; });
    if (!observed) continue;
    ++result.observed_samples;
    if (AnyNeighbour(key, [&](const octomap::OcTreeKey& n) { return occupied_keys.count(n) > 0; })) {
      ++result.covered_samples;
    }
  }
  result.static_map_precision = Ratio(result.precise_voxels, result.occupied_voxels, 0.0);
  result.static_map_completeness = Ratio(result.covered_samples, result.observed_samples, 0.0);
  return result;
}

}  // namespace dynamap::mapping
