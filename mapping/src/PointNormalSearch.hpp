// The k-d tree registration and normal estimation search in (pcl::search::KdTree's
// interface, so that ICP takes it as its target search), asking FLANN's tree directly.
//
// Why not pcl::search::KdTree itself: Debian's FLANN is built with OpenMP, and its
// knnSearch/radiusSearch open a parallel region for every call, which PCL's KdTreeFLANN
// makes once per query point. Even with one thread that costs a heap-allocated team and a
// futex system call per query; in the SLAM loop's registration that was seven eighths of
// its time on the two-core machine (docs/BENCHMARKS.md). The index is the one KdTreeFLANN
// builds (a single k-d tree, 15 points per leaf, exact search), so the neighbours are the
// same.
#pragma once

#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <flann/flann.hpp>
#include <memory>
#include <vector>

namespace dynamap::mapping::internal {

class PointNormalSearch : public pcl::search::KdTree<pcl::PointNormal> {
 public:
  using Base = pcl::search::KdTree<pcl::PointNormal>;
  using Ptr = std::shared_ptr<PointNormalSearch>;
  using Base::nearestKSearch;
  using Base::radiusSearch;

  PointNormalSearch();

  // Indexes the finite points of `cloud` (only those in `indices` when given) by x, y, z.
  void setInputCloud(const PointCloudConstPtr& cloud,
                     const IndicesConstPtr& indices = IndicesConstPtr()) override;

  // The k nearest indexed points (cloud indices), nearest first; the count found.
  int nearestKSearch(const pcl::PointNormal& point, int k, pcl::Indices& k_indices,
                     std::vector<float>& k_sqr_distances) const override;

  // The indexed points within `radius` (at most max_nn when it is not 0), nearest first
  // when the results are sorted; the count found.
  int radiusSearch(const pcl::PointNormal& point, double radius, pcl::Indices& k_indices,
                   std::vector<float>& k_sqr_distances, unsigned int max_nn = 0) const override;

 private:
  using Index = flann::KDTreeSingleIndex<flann::L2_Simple<float>>;

  std::vector<float> xyz_;                 // Indexed points, three floats each.
  std::vector<pcl::index_t> cloud_index_;  // Cloud index of each indexed point.
  std::unique_ptr<Index> index_;
  flann::SearchParams params_;
};

}  // namespace dynamap::mapping::internal
