#include "dynamap/mapping/MapExport.hpp"

#include <algorithm>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "dynamap/robotio/AtomicFile.hpp"

namespace dynamap::mapping {
namespace {

bool Occupied(const DualOcTree& tree, const DualOcTreeNode& node, MapChannel channel) {
  return channel == MapChannel::kStatic ? tree.IsStaticOccupied(node)
                                        : tree.IsDynamicOccupied(node);
}

// Calls f(key) for every leaf-size voxel under the leaf iterator's current node.
template <typename F>
void ForEachLeafVoxel(const DualOcTree& tree, const octomap::OcTreeKey& key, unsigned depth,
                      F&& f) {
  const unsigned cells = 1u << (tree.getTreeDepth() - depth);
  if (cells == 1) {
    f(key);
    return;
  }
  // The iterator's key is the node's centre key; its first leaf is half the cube below.
  const int half = static_cast<int>(cells / 2);
  for (unsigned dx = 0; dx < cells; ++dx) {
    for (unsigned dy = 0; dy < cells; ++dy) {
      for (unsigned dz = 0; dz < cells; ++dz) {
        f(octomap::OcTreeKey(static_cast<octomap::key_type>(key[0] - half + static_cast<int>(dx)),
                             static_cast<octomap::key_type>(key[1] - half + static_cast<int>(dy)),
                             static_cast<octomap::key_type>(key[2] - half + static_cast<int>(dz))));
      }
    }
  }
}

}  // namespace

robotio::PointList OccupiedVoxelCentres(const DualOcTree& tree, MapChannel channel) {
  robotio::PointList points;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    if (!Occupied(tree, *it, channel)) continue;
    ForEachLeafVoxel(tree, it.getKey(), it.getDepth(), [&](const octomap::OcTreeKey& key) {
      const octomap::point3d c = tree.keyToCoord(key);
      points.emplace_back(c.x(), c.y(), c.z());
    });
  }
  return points;
}

robotio::Status WriteTopDownPng(const DualOcTree& tree, const std::string& file) {
  if (tree.getRoot() == nullptr) return robotio::Error{file + ": the map is empty"};
  // Bounds in leaf keys over all leaves.
  int min_x = std::numeric_limits<int>::max(), min_y = min_x, max_x = -min_x, max_y = -min_x;
  double min_z = std::numeric_limits<double>::max(), max_z = -min_z;
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const int half = static_cast<int>((1u << (tree.getTreeDepth() - it.getDepth())) / 2);
    const octomap::OcTreeKey k = it.getKey();
    min_x = std::min(min_x, k[0] - half);
    max_x = std::max(max_x, k[0] + std::max(half - 1, 0));
    min_y = std::min(min_y, k[1] - half);
    max_y = std::max(max_y, k[1] + std::max(half - 1, 0));
    min_z = std::min(min_z, static_cast<double>(it.getZ()));
    max_z = std::max(max_z, static_cast<double>(it.getZ()));
  }
  const int width = max_x - min_x + 1, height = max_y - min_y + 1;
  if (static_cast<long long>(width) * height > 64ll * 1024 * 1024) {
    return robotio::Error{file + ": the map is too large for a top-down image"};
  }
  // Per column: 0 unknown, 1 free seen, 2 static, 3 dynamic; plus the top static height.
  std::vector<std::uint8_t> kind(static_cast<std::size_t>(width) * height, 0);
  std::vector<float> top(kind.size(), -std::numeric_limits<float>::max());
  for (auto it = tree.begin_leafs(), end = tree.end_leafs(); it != end; ++it) {
    const bool dynamic = tree.IsDynamicOccupied(*it);
    const bool occupied = tree.IsStaticOccupied(*it);
    const std::uint8_t k = dynamic ? 3 : occupied ? 2 : 1;
    // Height of the node's topmost leaf centre.
    const auto node_top = static_cast<float>(it.getZ() + it.getSize() / 2 - tree.getResolution() / 2);
    const int cells = static_cast<int>(1u << (tree.getTreeDepth() - it.getDepth()));
    const int first_x = it.getKey()[0] - cells / 2, first_y = it.getKey()[1] - cells / 2;
    for (int x = first_x; x < first_x + cells; ++x) {
      for (int y = first_y; y < first_y + cells; ++y) {
        const std::size_t cell =
            static_cast<std::size_t>(max_y - y) * width + static_cast<std::size_t>(x - min_x);
        kind[cell] = std::max(kind[cell], k);
        if (occupied) top[cell] = std::max(top[cell], node_top);
      }
    }
  }
  cv::Mat image(height, width, CV_8UC3);
  const double z_span = std::max(max_z - min_z, 1e-6);
  for (int row = 0; row < height; ++row) {
    for (int col = 0; col < width; ++col) {
      const std::size_t cell = static_cast<std::size_t>(row) * width + col;
      cv::Vec3b bgr(235, 225, 220);  // Unknown.
      if (kind[cell] == 1) bgr = cv::Vec3b(255, 255, 255);
      if (kind[cell] == 2) {
        const double t = std::clamp((top[cell] - min_z) / z_span, 0.0, 1.0);
        const auto grey = static_cast<std::uint8_t>(190 - 150 * t);
        bgr = cv::Vec3b(grey, grey, grey);
      }
      if (kind[cell] == 3) bgr = cv::Vec3b(0, 0, 230);
      image.at<cv::Vec3b>(row, col) = bgr;
    }
  }
  // Small maps are enlarged (whole pixels per voxel, no smoothing) so the longer side has
  // about 600 pixels: a 5 × 6 m room is 100 × 120 voxels.
  const int scale = std::clamp(600 / std::max(width, height), 1, 8);
  if (scale > 1) cv::resize(image, image, cv::Size(), scale, scale, cv::INTER_NEAREST);
  return robotio::WriteFileAtomically(file, [&](const std::string& temporary) {
    return cv::imwrite(temporary, image, {cv::IMWRITE_PNG_COMPRESSION, 6});
  });
}

}  // namespace dynamap::mapping
