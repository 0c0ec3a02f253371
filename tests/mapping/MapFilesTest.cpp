#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/imgcodecs.hpp>

#include "SyntheticScene.hpp"
#include "ThesisRuleConfig.hpp"
#include "dynamap/mapping/DualMap.hpp"
#include "dynamap/mapping/MapExport.hpp"
#include "dynamap/mapping/MapFiles.hpp"
#include "dynamap/mapping/PointCloudFiles.hpp"

namespace dynamap::mapping {
namespace {

const std::string kGeb079 = std::string(DYNAMAP_SHARED_DATA_DIR) + "/octomap/geb079.bt";

std::string ReadBytes(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void WriteBytes(const std::string& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary) << bytes;
}

std::string Temp(const std::string& name) { return ::testing::TempDir() + "/" + name; }

// A map with a wall (static) and a person who stepped into seen free space (dynamic).
DualMap SceneMap() {
  DualMap map{ThesisRuleConfig()};
  testing::SyntheticScene scene;
  map.InsertRays(testing::CastScan(scene, {0, 0, 0}, 4.0f, 1.0f));
  scene.boxes.push_back({{1.5f, -0.2f, -0.5f}, {1.8f, 0.2f, 1.2f}});
  map.InsertRays(testing::CastScan(scene, {0, 0, 0}, 4.0f, 1.0f));
  return map;
}

TEST(MapFilesTest, Geb079OpensWithItsNodeCountAndReexportsByteIdentical) {
  auto map = LoadMap(kGeb079);
  ASSERT_TRUE(map) << map.error().message;
  EXPECT_EQ((*map)->size(), 532566u);
  EXPECT_DOUBLE_EQ((*map)->getResolution(), 0.08);
  const std::string out = Temp("geb079_reexport.bt");
  ASSERT_TRUE(ExportBinary(**map, MapChannel::kStatic, out));
  EXPECT_TRUE(ReadBytes(out) == ReadBytes(kGeb079));
  // Imported as a static map: nothing in it is dynamic.
  EXPECT_TRUE(OccupiedVoxelCentres(**map, MapChannel::kDynamic).empty());
}

TEST(MapFilesTest, ExportedChannelsReadBackAsStandardOcTrees) {
  const DualMap map = SceneMap();
  for (MapChannel channel : {MapChannel::kStatic, MapChannel::kDynamic}) {
    const std::string file = Temp(channel == MapChannel::kStatic ? "static.bt" : "dynamic.bt");
    ASSERT_TRUE(ExportBinary(map.tree(), channel, file));
    octomap::OcTree plain(0.1);
    ASSERT_TRUE(plain.readBinary(file));
    EXPECT_EQ(plain.size(), map.tree().size());
    // Every leaf agrees on occupancy with the channel it came from.
    for (auto it = map.tree().begin_leafs(); it != map.tree().end_leafs(); ++it) {
      const octomap::OcTreeNode* node = plain.search(it.getKey(), it.getDepth());
      ASSERT_NE(node, nullptr);
      const bool expected = channel == MapChannel::kStatic ? map.tree().IsStaticOccupied(*it)
                                                           : map.tree().IsDynamicOccupied(*it);
      EXPECT_EQ(plain.isNodeOccupied(node), expected);
    }
  }
}

TEST(MapFilesTest, PlainOcTreeOtImportsAsAStaticMap) {
  octomap::OcTree plain(0.1);
  plain.updateNode(octomap::point3d(1.0f, 2.0f, 0.5f), true);
  plain.updateNode(octomap::point3d(0.5f, 0.5f, 0.5f), false);
  const std::string file = Temp("plain.ot");
  ASSERT_TRUE(plain.write(file));
  auto map = LoadMap(file);
  ASSERT_TRUE(map) << map.error().message;
  EXPECT_EQ((*map)->size(), plain.size());
  const DualOcTreeNode* node = (*map)->search(1.0, 2.0, 0.5);
  ASSERT_NE(node, nullptr);
  EXPECT_TRUE((*map)->IsStaticOccupied(*node));
  EXPECT_FALSE((*map)->IsDynamicOccupied(*node));
}

TEST(MapFilesTest, NonMapFileIsAnErrorNamingTheFile) {
  const std::string file = Temp("not_a_map.ot");
  WriteBytes(file, "hello world\nthis is not an octree\n");
  auto map = LoadMap(file);
  ASSERT_FALSE(map);
  EXPECT_NE(map.error().message.find(file), std::string::npos);
  EXPECT_NE(map.error().message.find("not an OctoMap"), std::string::npos);
  auto missing = LoadMap(Temp("does_not_exist.ot"));
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().message.find("does_not_exist.ot"), std::string::npos);
}

TEST(MapFilesTest, TruncatedFilesAreErrors) {
  const DualMap map = SceneMap();
  const std::string ot = Temp("full.ot");
  ASSERT_TRUE(SaveDualMap(map.tree(), ot));
  const std::string ot_bytes = ReadBytes(ot);
  const std::string bt_bytes = ReadBytes(kGeb079);
  for (const auto& [bytes, name] : {std::pair{ot_bytes, std::string("cut.ot")},
                                    std::pair{bt_bytes, std::string("cut.bt")}}) {
    for (const double keep : {0.999, 0.5, 0.05}) {
      const std::string file = Temp(name);
      WriteBytes(file, bytes.substr(0, static_cast<std::size_t>(bytes.size() * keep)));
      auto loaded = LoadMap(file);
      ASSERT_FALSE(loaded) << name << " kept " << keep;
      EXPECT_NE(loaded.error().message.find(file), std::string::npos);
    }
  }
}

TEST(MapFilesTest, OtherTreeTypesAreRejected) {
  const std::string file = Temp("color.ot");
  WriteBytes(file, "# Octomap OcTree file\nid ColorOcTree\nsize 1\nres 0.1\ndata\n1234567\0");
  auto loaded = LoadMap(file);
  ASSERT_FALSE(loaded);
  EXPECT_NE(loaded.error().message.find("ColorOcTree"), std::string::npos);
}

TEST(MapFilesTest, PlyAndPcdRoundTripTheVoxelCentres) {
  const DualMap map = SceneMap();
  for (MapChannel channel : {MapChannel::kStatic, MapChannel::kDynamic}) {
    const robotio::PointList centres = OccupiedVoxelCentres(map.tree(), channel);
    ASSERT_FALSE(centres.empty());
    ASSERT_TRUE(WritePly(centres, Temp("c.ply")));
    ASSERT_TRUE(WritePcd(centres, Temp("c.pcd")));
    for (auto read : {ReadPly(Temp("c.ply")), ReadPcd(Temp("c.pcd"))}) {
      ASSERT_TRUE(read) << read.error().message;
      ASSERT_EQ(read->size(), centres.size());
      for (std::size_t i = 0; i < centres.size(); ++i) {
        EXPECT_NEAR(((*read)[i] - centres[i]).norm(), 0.0f, 2e-6f);
      }
    }
  }
  WriteBytes(Temp("short.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nend_header\n1 2 3\n");
  EXPECT_FALSE(ReadPly(Temp("short.ply")));
}

TEST(MapFilesTest, OccupiedCentresOfAPrunedNodeCoverEveryLeafVoxel) {
  DualOcTree tree(0.1);
  DualOcTreeNode* node = tree.CreateRoot();
  for (unsigned d = 0; d < 14; ++d) node = tree.createNodeChild(node, 7);
  node->SetStaticLogOdds(2.0f);  // A pruned depth-14 node: 4x4x4 leaf voxels.
  EXPECT_EQ(OccupiedVoxelCentres(tree, MapChannel::kStatic).size(), 64u);
}

TEST(MapFilesTest, TopDownPngShowsStaticGreyAndDynamicRed) {
  const DualMap map = SceneMap();
  const std::string file = Temp("top.png");
  ASSERT_TRUE(WriteTopDownPng(map.tree(), file));
  const cv::Mat image = cv::imread(file, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  int red = 0, grey = 0;
  for (int r = 0; r < image.rows; ++r) {
    for (int c = 0; c < image.cols; ++c) {
      const cv::Vec3b p = image.at<cv::Vec3b>(r, c);
      if (p[2] > 200 && p[1] < 50 && p[0] < 50) ++red;
      if (p[0] == p[1] && p[1] == p[2] && p[0] < 200) ++grey;
    }
  }
  // A room-sized map is enlarged to be seen (whole pixels per voxel).
  EXPECT_GE(std::max(image.cols, image.rows), 300);
  EXPECT_GE(red, 8);    // The person's seen front face: 0.4 m wide at 5 cm.
  EXPECT_GT(grey, 50);  // The wall and the floor.
}

}  // namespace
}  // namespace dynamap::mapping
