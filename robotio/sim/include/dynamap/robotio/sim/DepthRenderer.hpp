// Ray-cast depth and ground-truth label images of a world (Embree ray packets on every
// core), with the Kinect error model applied per pixel.
#pragma once

#include <Eigen/Geometry>
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "dynamap/robotio/DepthFrame.hpp"
#include "dynamap/robotio/Intrinsics.hpp"
#include "dynamap/robotio/sim/KinectModel.hpp"
#include "dynamap/robotio/sim/World.hpp"
#include "dynamap/robotio/sim/WorldTimeline.hpp"

namespace dynamap::robotio::sim {

struct RenderedImage {
  DepthFrame depth;   // Only sensor_id, size, intrinsics and depth_mm are filled.
  LabelFrame labels;  // Label of every pixel with a depth, 0 elsewhere.
};

class DepthRenderer {
 public:
  // Builds the fixed geometry (floor, holes, walls, steps, furniture that never moves).
  // threads: render threads (at least 1).
  DepthRenderer(const World& world, int threads);
  ~DepthRenderer();
  DepthRenderer(const DepthRenderer&) = delete;
  DepthRenderer& operator=(const DepthRenderer&) = delete;

  // Replaces the moving geometry (doors, moved furniture, people) for the next renders.
  void SetMovingSolids(const std::vector<Solid>& solids);

  // One image from a camera at T_world_kinect (optical frame). Depth nearer than
  // min_range_m is dropped; `noise_key` makes the noise of this image reproducible.
  [[nodiscard]] RenderedImage Render(const Eigen::Isometry3d& T_world_kinect,
                                     const Intrinsics& intrinsics, double min_range_m,
                                     const KinectModelConfig& model,
                                     std::uint64_t noise_key) const;

  // Rays cast since construction (for the benchmark).
  [[nodiscard]] std::uint64_t rays_cast() const { return rays_cast_.load(); }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int threads_ = 1;
  mutable std::atomic<std::uint64_t> rays_cast_{0};
};

}  // namespace dynamap::robotio::sim
