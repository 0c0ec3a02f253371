// Dynamic-map accuracy as DESIGN.md (Evaluation) defines it: point-wise static/dynamic/
// associated accuracy (KTH DynamicMap benchmark) and the static map's precision and
// completeness against true static surface samples (thesis 5.4).
#pragma once

#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include <octomap/OcTreeKey.h>

#include "dynamap/mapping/DualOcTree.hpp"
#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/DepthProjection.hpp"
#include "dynamap/robotio/Rig.hpp"

namespace dynamap::mapping {

struct PointAccuracy {
  std::uint64_t static_points = 0;   // Labelled static depth points seen.
  std::uint64_t dynamic_points = 0;  // Labelled dynamic depth points seen.
  std::uint64_t static_kept = 0;     // ... whose voxel is occupied in the final static map.
  std::uint64_t dynamic_removed = 0; // ... whose voxel is not.
  double static_accuracy = 0.0;      // SA = kept static / all static (1 when none).
  double dynamic_accuracy = 0.0;     // DA = removed dynamic / all dynamic (1 when none).
  double associated_accuracy = 0.0;  // AA = sqrt(SA * DA).
  // Dynamic points in voxels whose centre lies less than two voxels above the floor plane
  // (z = 0 of the map), where a person's feet share the floor's voxels: the floor's own
  // layer stays occupied however the map is updated (the layer above it is seen free
  // again only with MappingConfig::floor_plane).
  std::uint64_t dynamic_points_near_floor = 0;
  std::uint64_t dynamic_kept_near_floor = 0;
  // DA over the dynamic points above that layer (1 when none).
  double dynamic_accuracy_above_floor = 0.0;
  // The same split for the static points: the floor's own points and what stands on it.
  std::uint64_t static_points_near_floor = 0;
  std::uint64_t static_kept_near_floor = 0;
  // SA over the static points above that layer (1 when none).
  double static_accuracy_above_floor = 0.0;
};

// Where the accuracy was lost: voxels holding labelled static points that the final
// static map does not keep, and voxels holding labelled dynamic points that it does
// (voxel centres in the map frame, with how many points each stands for).
struct MisclassifiedVoxels {
  robotio::PointList static_lost;
  std::vector<std::uint64_t> static_lost_points;
  robotio::PointList dynamic_kept;
  std::vector<std::uint64_t> dynamic_kept_points;
};

// The voxels as CSV: a comment line, the header x,y,z,static_points_lost,
// dynamic_points_kept, then one voxel per line (for a closer look at heights, or in a
// point-cloud viewer).
[[nodiscard]] std::string MisclassifiedVoxelsCsv(const MisclassifiedVoxels& misclassified);

// Collects the labelled depth points of a run by voxel (so a long run needs memory per
// voxel, not per point), then scores them against the final static map.
class PointAccuracyCounter {
 public:
  // `stride` takes every stride-th pixel in u and v; points beyond `max_range_m` along the
  // ray are not counted (they never enter the map).
  PointAccuracyCounter(double resolution_m, double max_range_m, int stride);

  void Add(const robotio::DepthFrame& depth, const robotio::LabelFrame& labels,
           const robotio::KinectMount& mount, const Eigen::Isometry3d& T_map_base);

  [[nodiscard]] PointAccuracy Evaluate(const DualOcTree& final_map) const;
  [[nodiscard]] MisclassifiedVoxels Misclassified(const DualOcTree& final_map) const;

 private:
  struct Counts {
    std::uint64_t static_points = 0;
    std::uint64_t dynamic_points = 0;
  };
  double max_range_m_;
  int stride_;
  DualOcTree key_frame_;  // Only for key arithmetic at the map's resolution.
  std::unordered_map<octomap::OcTreeKey, Counts, octomap::OcTreeKey::KeyHash> counts_;
};

struct SurfaceAccuracy {
  std::uint64_t occupied_voxels = 0;      // Occupied static leaf voxels.
  std::uint64_t precise_voxels = 0;       // ... within one voxel of a true surface sample.
  std::uint64_t observed_samples = 0;     // Sample voxels within one voxel of observed space.
  std::uint64_t covered_samples = 0;      // ... within one voxel of an occupied static voxel.
  double static_map_precision = 0.0;      // precise / occupied (0 when the map is empty).
  double static_map_completeness = 0.0;   // covered / observed (0 when nothing observed).
};

// "Within one voxel" = in the same or one of the 26 neighbouring leaf voxels. Samples are
// in the map frame; only samples next to observed voxels count for completeness (surfaces
// the robot could see).
[[nodiscard]] SurfaceAccuracy EvaluateStaticSurfaces(const DualOcTree& map,
                                                     const robotio::PointList& surface_samples);

}  // namespace dynamap::mapping
