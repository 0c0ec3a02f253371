// The k-d tree that registration, calibration and normal estimation search in: PCL's
// search::KdTree interface (so ICP takes it as its target search), FLANN's tree asked
// directly. Include only where PCL is used; it brings PCL and FLANN headers.
//
// Why not pcl::search::KdTree itself: Debian's FLANN is built with OpenMP, and its
// knnSearch/radiusSearch open a parallel region for every call, which PCL's KdTreeFLANN
// makes once per query point. Even with one thread that costs a heap-allocated team and a
// futex system call per query: nine tenths of the SLAM loop's registration time, and five
// sixths of a calibration session's, on the two-core machine (docs/BENCHMARKS.md). The
// index is the one KdTreeFLANN builds (a single k-d tree, 15 points per leaf, exact
// search, x/y/z only), so the neighbours are the same.
#pragma once

#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <algorithm>
#include <cmath>
#include <flann/flann.hpp>
#include <memory>
#include <vector>

namespace dynamap::mapping {

template <typename PointT>
class FlannPointSearch : public pcl::search::KdTree<PointT> {
 public:
  using Base = pcl::search::KdTree<PointT>;
  using Ptr = std::shared_ptr<FlannPointSearch>;
  using Base::nearestKSearch;
  using Base::radiusSearch;
  using typename Base::IndicesConstPtr;
  using typename Base::PointCloudConstPtr;

  FlannPointSearch() : Base(/*sorted=*/true), params_(-1, 0.0f, true) {}

  // Indexes the finite points of `cloud` (only those in `indices` when given) by x, y, z.
  void setInputCloud(const PointCloudConstPtr& cloud,
                     const IndicesConstPtr& indices = IndicesConstPtr()) override {
    this->input_ = cloud;
    this->indices_ = indices;
    xyz_.clear();
    cloud_index_.clear();
    index_.reset();
    if (!cloud) return;
    const auto add = [this, &cloud](pcl::index_t i) {
      const PointT& p = (*cloud)[static_cast<std::size_t>(i)];
      if (!IsFinite(p)) return;
      xyz_.insert(xyz_.end(), {p.x, p.y, p.z});
      cloud_index_.push_back(i);
    };
    if (indices) {
      for (const pcl::index_t i : *indices) add(i);
    } else {
      for (std::size_t i = 0; i < cloud->size(); ++i) add(static_cast<pcl::index_t>(i));
    }
    if (cloud_index_.empty()) return;
    index_ = std::make_unique<Index>(flann::Matrix<float>(xyz_.data(), cloud_index_.size(), 3),
                                     flann::KDTreeSingleIndexParams(15));
    index_->buildIndex();
  }

  // The k nearest indexed points (cloud indices), nearest first; the count found.
  int nearestKSearch(const PointT& point, int k, pcl::Indices& k_indices,
                     std::vector<float>& k_sqr_distances) const override {
    k_indices.clear();
    k_sqr_distances.clear();
    if (!index_ || k <= 0 || !IsFinite(point)) return 0;
    const std::size_t wanted = std::min(static_cast<std::size_t>(k), cloud_index_.size());
    flann::KNNSimpleResultSet<float> result(wanted);
    const float query[3] = {point.x, point.y, point.z};
    index_->findNeighbors(result, query, params_);
    const std::size_t found = std::min(result.size(), wanted);
    std::vector<std::size_t> positions(found);
    k_sqr_distances.resize(found);
    result.copy(positions.data(), k_sqr_distances.data(), found, /*sorted=*/true);
    return ToCloudIndices(positions, k_indices);
  }

  // The indexed points within `radius` (at most max_nn when it is not 0), nearest first
  // when the results are sorted; the count found.
  int radiusSearch(const PointT& point, double radius, pcl::Indices& k_indices,
                   std::vector<float>& k_sqr_distances, unsigned int max_nn = 0) const override {
    k_indices.clear();
    k_sqr_distances.clear();
    if (!index_ || radius <= 0.0 || !IsFinite(point)) return 0;
    const auto radius_sq = static_cast<float>(radius * radius);
    const float query[3] = {point.x, point.y, point.z};
    std::vector<std::size_t> positions;
    const auto collect = [&](auto& result) {
      index_->findNeighbors(result, query, params_);
      positions.resize(result.size());
      k_sqr_distances.resize(result.size());
      result.copy(positions.data(), k_sqr_distances.data(), result.size(), this->sorted_results_);
    };
    if (max_nn > 0) {
      flann::KNNRadiusResultSet<float> result(radius_sq, max_nn);
      collect(result);
    } else {
      flann::RadiusResultSet<float> result(radius_sq);
      collect(result);
    }
    return ToCloudIndices(positions, k_indices);
  }

 private:
  using Index = flann::KDTreeSingleIndex<flann::L2_Simple<float>>;

  static bool IsFinite(const PointT& p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  }

  int ToCloudIndices(const std::vector<std::size_t>& positions, pcl::Indices& indices) const {
    indices.resize(positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) indices[i] = cloud_index_[positions[i]];
    return static_cast<int>(positions.size());
  }

  std::vector<float> xyz_;                 // Indexed points, three floats each.
  std::vector<pcl::index_t> cloud_index_;  // Cloud index of each indexed point.
  std::unique_ptr<Index> index_;
  flann::SearchParams params_;
};

}  // namespace dynamap::mapping
