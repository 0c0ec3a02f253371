// The k-d tree of registration and calibration answers as PCL's own does (same neighbours, same
// distances), with the cloud's indices, subsets and invalid points handled alike.
#include <gtest/gtest.h>
#include <pcl/search/kdtree.h>

#include <cmath>
#include <limits>
#include <random>

#include "dynamap/mapping/FlannPointSearch.hpp"

namespace dynamap::mapping {
namespace {

using Cloud = pcl::PointCloud<pcl::PointNormal>;

Cloud::Ptr RandomCloud(std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> coordinate(-2.0f, 2.0f);
  auto cloud = std::make_shared<Cloud>();
  cloud->resize(n);
  for (pcl::PointNormal& p : *cloud) {
    p.x = coordinate(random);
    p.y = coordinate(random);
    p.z = 0.5f * coordinate(random);
  }
  return cloud;
}

TEST(FlannPointSearch, FindsTheNeighboursPclsKdTreeFinds) {
  const Cloud::Ptr cloud = RandomCloud(5000, 1);
  (*cloud)[17].x = std::numeric_limits<float>::quiet_NaN();  // Never returned.
  pcl::search::KdTree<pcl::PointNormal> pcl_tree;
  pcl_tree.setInputCloud(cloud);
  FlannPointSearch<pcl::PointNormal> search;
  search.setInputCloud(cloud);
  const Cloud::Ptr queries = RandomCloud(300, 2);
  for (const pcl::PointNormal& q : *queries) {
    for (const int k : {1, 10}) {
      pcl::Indices expected, got;
      std::vector<float> expected_sq, got_sq;
      ASSERT_EQ(search.nearestKSearch(q, k, got, got_sq),
                pcl_tree.nearestKSearch(q, k, expected, expected_sq));
      EXPECT_EQ(got, expected);
      EXPECT_EQ(got_sq, expected_sq);
      for (const pcl::index_t i : got) EXPECT_NE(i, 17);
    }
    pcl::Indices expected, got;
    std::vector<float> expected_sq, got_sq;
    ASSERT_EQ(search.radiusSearch(q, 0.3, got, got_sq),
              pcl_tree.radiusSearch(q, 0.3, expected, expected_sq));
    EXPECT_EQ(got, expected);
    EXPECT_EQ(got_sq, expected_sq);
    ASSERT_EQ(search.radiusSearch(q, 0.3, got, got_sq, 4),
              pcl_tree.radiusSearch(q, 0.3, expected, expected_sq, 4));
    EXPECT_EQ(got, expected);
  }
}

// Calibration estimates normals of x/y/z clouds with radius searches.
TEST(FlannPointSearch, RadiusSearchOnPlainPointsMatchesPcl) {
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  for (const pcl::PointNormal& p : *RandomCloud(3000, 4)) cloud->emplace_back(p.x, p.y, p.z);
  pcl::search::KdTree<pcl::PointXYZ> pcl_tree;
  pcl_tree.setInputCloud(cloud);
  FlannPointSearch<pcl::PointXYZ> search;
  search.setInputCloud(cloud);
  for (std::size_t i = 0; i < cloud->size(); i += 97) {
    pcl::Indices expected, got;
    std::vector<float> expected_sq, got_sq;
    ASSERT_EQ(search.radiusSearch((*cloud)[i], 0.25, got, got_sq),
              pcl_tree.radiusSearch((*cloud)[i], 0.25, expected, expected_sq));
    EXPECT_EQ(got, expected);
    EXPECT_EQ(got_sq, expected_sq);
  }
}

TEST(FlannPointSearch, SearchesOnlyTheGivenIndicesAndAnswersWithCloudIndices) {
  const Cloud::Ptr cloud = RandomCloud(1000, 3);
  auto odd = std::make_shared<pcl::Indices>();
  for (pcl::index_t i = 1; i < 1000; i += 2) odd->push_back(i);
  FlannPointSearch<pcl::PointNormal> search;
  search.setInputCloud(cloud, odd);
  pcl::Indices found;
  std::vector<float> sq;
  // Each even point's nearest is another point; each odd point finds itself.
  ASSERT_EQ(search.nearestKSearch((*cloud)[10], 3, found, sq), 3);
  for (const pcl::index_t i : found) EXPECT_EQ(i % 2, 1);
  ASSERT_EQ(search.nearestKSearch((*cloud)[11], 1, found, sq), 1);
  EXPECT_EQ(found[0], 11);
  EXPECT_FLOAT_EQ(sq[0], 0.0f);
  // More neighbours than points: all of them. Invalid query or empty index: none.
  EXPECT_EQ(search.nearestKSearch((*cloud)[0], 2000, found, sq), 500);
  pcl::PointNormal nan;
  nan.x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(search.nearestKSearch(nan, 1, found, sq), 0);
  FlannPointSearch<pcl::PointNormal> empty;
  empty.setInputCloud(std::make_shared<Cloud>());
  EXPECT_EQ(empty.nearestKSearch((*cloud)[0], 1, found, sq), 0);
  EXPECT_TRUE(found.empty());
}

}  // namespace
}  // namespace dynamap::mapping
