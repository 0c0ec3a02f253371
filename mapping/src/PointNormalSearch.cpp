#include "PointNormalSearch.hpp"

#include <algorithm>
#include <cmath>

namespace dynamap::mapping::internal {
namespace {

bool IsFinite(const pcl::PointNormal& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

}  // namespace

PointNormalSearch::PointNormalSearch() : Base(/*sorted=*/true), params_(-1, 0.0f, true) {}

void PointNormalSearch::setInputCloud(const PointCloudConstPtr& cloud,
                                      const IndicesConstPtr& indices) {
  input_ = cloud;
  indices_ = indices;
  xyz_.clear();
  cloud_index_.clear();
  index_.reset();
  if (!cloud) return;
  const auto add = [this, &cloud](pcl::index_t i) {
    const pcl::PointNormal& p = (*cloud)[static_cast<std::size_t>(i)];
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

int PointNormalSearch::nearestKSearch(const pcl::PointNormal& point, int k, pcl::Indices& k_indices,
                                      std::vector<float>& k_sqr_distances) const {
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
  k_indices.resize(found);
  for (std::size_t i = 0; i < found; ++i) k_indices[i] = cloud_index_[positions[i]];
  return static_cast<int>(found);
}

int PointNormalSearch::radiusSearch(const pcl::PointNormal& point, double radius,
                                    pcl::Indices& k_indices, std::vector<float>& k_sqr_distances,
                                    unsigned int max_nn) const {
  k_indices.clear();
  k_sqr_distances.clear();
  if (!index_ || radius <= 0.0 || !IsFinite(point)) return 0;
  const auto radius_sq = static_cast<float>(radius * radius);
  const float query[3] = {point.x, point.y, point.z};
  std::vector<std::size_t> positions;
  if (max_nn > 0) {
    flann::KNNRadiusResultSet<float> result(radius_sq, max_nn);
    index_->findNeighbors(result, query, params_);
    positions.resize(result.size());
    k_sqr_distances.resize(result.size());
    result.copy(positions.data(), k_sqr_distances.data(), result.size(), sorted_results_);
  } else {
    flann::RadiusResultSet<float> result(radius_sq);
    index_->findNeighbors(result, query, params_);
    positions.resize(result.size());
    k_sqr_distances.resize(result.size());
    result.copy(positions.data(), k_sqr_distances.data(), result.size(), sorted_results_);
  }
  k_indices.resize(positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) k_indices[i] = cloud_index_[positions[i]];
  return static_cast<int>(positions.size());
}

}  // namespace dynamap::mapping::internal
