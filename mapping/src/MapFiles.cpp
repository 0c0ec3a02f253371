#include "dynamap/mapping/MapFiles.hpp"

#include <octomap/AbstractOcTree.h>
#include <octomap/OcTree.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <sstream>

#include "dynamap/robotio/AtomicFile.hpp"

namespace dynamap::mapping {
namespace {

constexpr const char* kOtFirstLine = "# Octomap OcTree file";
constexpr const char* kBtFirstLine = "# Octomap OcTree binary file";
constexpr unsigned kMaxDepth = 16;

struct Header {
  bool binary = false;
  std::string id;
  std::size_t size = 0;
  double resolution = 0.0;
  std::size_t data_offset = 0;  // First byte after the "data" line.
};

// Parses the text header OctoMap writes before the node data.
robotio::Expected<Header> ParseHeader(const std::string& bytes, const std::string& file) {
  std::size_t pos = 0;
  auto next_line = [&](std::string* line) {
    if (pos >= bytes.size()) return false;
    const std::size_t end = bytes.find('\n', pos);
    if (end == std::string::npos) return false;
    *line = bytes.substr(pos, end - pos);
    if (!line->empty() && line->back() == '\r') line->pop_back();
    pos = end + 1;
    return true;
  };
  Header header;
  std::string line;
  if (!next_line(&line) || (line.rfind(kOtFirstLine, 0) != 0 && line.rfind(kBtFirstLine, 0) != 0)) {
    return robotio::Error{file + ": not an OctoMap map file (expected a first line '" +
                          kBtFirstLine + "' or '" + kOtFirstLine + "')"};
  }
  header.binary = line.rfind(kBtFirstLine, 0) == 0;
  bool have_size = false, have_res = false;
  while (next_line(&line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream in(line);
    std::string token;
    in >> token;
    if (token == "data") {
      header.data_offset = pos;
      if (header.id.empty() || !have_size || !have_res) break;
      if (!(header.resolution > 0.0)) {
        return robotio::Error{file + ": header 'res' must be positive"};
      }
      return header;
    }
    if (token == "id") in >> header.id;
    if (token == "size") have_size = static_cast<bool>(in >> header.size);
    if (token == "res") have_res = static_cast<bool>(in >> header.resolution);
  }
  return robotio::Error{file + ": truncated or malformed OctoMap header (needs id, size, res "
                               "and a 'data' line)"};
}

// Walks the node data without building anything, so that a truncated or corrupt file is
// an error here rather than undefined reads inside OctoMap. Returns the node count.
class DataWalker {
 public:
  DataWalker(const std::string& bytes, std::size_t offset, std::size_t payload, bool binary)
      : bytes_(bytes), pos_(offset), payload_(payload), binary_(binary) {}

  // Nodes found, or -1 when the data ends early, -2 when it is deeper than a tree can be.
  long long Walk() {
    long long count = 1;
    const int status = binary_ ? WalkBinary(0, &count) : WalkFull(0, &count);
    return status == 0 ? count : status;
  }

 private:
  int WalkFull(unsigned depth, long long* count) {
    if (pos_ + payload_ + 1 > bytes_.size()) return -1;
    pos_ += payload_;
    const auto children = static_cast<std::uint8_t>(bytes_[pos_++]);
    if (children != 0 && depth >= kMaxDepth) return -2;
    for (unsigned i = 0; i < 8; ++i) {
      if ((children >> i) & 1u) {
        ++*count;
        if (const int status = WalkFull(depth + 1, count); status != 0) return status;
      }
    }
    return 0;
  }

  int WalkBinary(unsigned depth, long long* count) {
    if (pos_ + 2 > bytes_.size()) return -1;
    const std::uint16_t bits = static_cast<std::uint8_t>(bytes_[pos_]) |
                               static_cast<std::uint16_t>(static_cast<std::uint8_t>(bytes_[pos_ + 1]) << 8);
    pos_ += 2;
    for (unsigned i = 0; i < 8; ++i) {
      const unsigned code = (bits >> (2 * i)) & 3u;
      if (code != 0) ++*count;
    }
    for (unsigned i = 0; i < 8; ++i) {
      if (((bits >> (2 * i)) & 3u) == 3u) {
        if (depth + 1 >= kMaxDepth) return -2;
        if (const int status = WalkBinary(depth + 1, count); status != 0) return status;
      }
    }
    return 0;
  }

  const std::string& bytes_;
  std::size_t pos_;
  std::size_t payload_;
  bool binary_;
};

void CopyStaticRecurs(const octomap::OcTree& from, const octomap::OcTreeNode* node,
                      DualOcTree& to, DualOcTreeNode* target, float dynamic_log_odds) {
  target->SetStaticLogOdds(node->getLogOdds());
  target->SetDynamicLogOdds(dynamic_log_odds);
  if (!from.nodeHasChildren(node)) return;
  for (unsigned i = 0; i < 8; ++i) {
    if (!from.nodeChildExists(node, i)) continue;
    CopyStaticRecurs(from, from.getNodeChild(node, i), to, to.createNodeChild(target, i),
                     dynamic_log_odds);
  }
}

// A plain OctoMap tree becomes the static channel; nothing in it is dynamic.
std::unique_ptr<DualOcTree> FromOcTree(const octomap::OcTree& plain) {
  auto tree = std::make_unique<DualOcTree>(plain.getResolution());
  if (plain.getRoot() != nullptr) {
    CopyStaticRecurs(plain, plain.getRoot(), *tree, tree->CreateRoot(),
                     tree->getClampingThresMinLog());
  }
  return tree;
}

void CopyChannelRecurs(const DualOcTree& from, const DualOcTreeNode* node, octomap::OcTree& to,
                       octomap::OcTreeNode* target, MapChannel channel) {
  target->setLogOdds(channel == MapChannel::kStatic ? node->StaticLogOdds()
                                                    : node->DynamicLogOdds());
  if (!from.nodeHasChildren(node)) return;
  for (unsigned i = 0; i < 8; ++i) {
    if (!from.nodeChildExists(node, i)) continue;
    CopyChannelRecurs(from, from.getNodeChild(node, i), to, to.createNodeChild(target, i),
                      channel);
  }
}

// octomap::OcTree with a way to create its root, so a copy can build the tree node by node.
class BuildableOcTree : public octomap::OcTree {
 public:
  using octomap::OcTree::OcTree;
  octomap::OcTreeNode* CreateRoot() {
    if (root == nullptr) {
      root = new octomap::OcTreeNode();
      ++tree_size;
      size_changed = true;
    }
    return root;
  }
};

}  // namespace

robotio::Status SaveDualMap(const DualOcTree& tree, const std::string& file) {
  std::ostringstream out(std::ios::binary);
  if (!tree.write(out)) return robotio::Error{file + ": could not serialise the map"};
  return robotio::WriteFileAtomically(file, out.str());
}

robotio::Expected<std::unique_ptr<DualOcTree>> LoadMap(const std::string& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return robotio::Error{file + ": cannot open map file"};
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto header = ParseHeader(bytes, file);
  if (!header) return header.error();

  std::size_t payload = 0;
  if (header->binary) {
    if (header->id != "OcTree") {
      return robotio::Error{file + ": binary tree type '" + header->id +
                            "' is not supported (expected OcTree)"};
    }
  } else if (header->id == "OcTree") {
    payload = sizeof(float);
  } else if (header->id == DualOcTree::kTreeType) {
    payload = 2 * sizeof(float);
  } else {
    return robotio::Error{file + ": tree type '" + header->id + "' is not a map dynamap opens "
                          "(expected " + DualOcTree::kTreeType + " or OcTree)"};
  }

  long long nodes = 0;
  if (header->size > 0) {
    nodes = DataWalker(bytes, header->data_offset, payload, header->binary).Walk();
    if (nodes == -1) {
      return robotio::Error{file + ": truncated: the node data ends before the tree is "
                            "complete (header size " + std::to_string(header->size) + ")"};
    }
    if (nodes == -2) return robotio::Error{file + ": corrupt node data (tree deeper than 16)"};
  }
  if (static_cast<std::size_t>(nodes) != header->size) {
    return robotio::Error{file + ": header says " + std::to_string(header->size) +
                          " nodes but the data holds " + std::to_string(nodes)};
  }

  std::istringstream stream(bytes, std::ios::binary);
  if (header->binary) {
    octomap::OcTree plain(header->resolution);
    if (!plain.readBinary(stream)) return robotio::Error{file + ": could not read the .bt data"};
    return FromOcTree(plain);
  }
  std::unique_ptr<octomap::AbstractOcTree> read(octomap::AbstractOcTree::read(stream));
  if (read == nullptr) return robotio::Error{file + ": could not read the .ot data"};
  if (auto* dual = dynamic_cast<DualOcTree*>(read.get())) {
    read.release();
    return std::unique_ptr<DualOcTree>(dual);
  }
  if (auto* plain = dynamic_cast<octomap::OcTree*>(read.get())) return FromOcTree(*plain);
  return robotio::Error{file + ": unexpected tree type '" + read->getTreeType() + "'"};
}

std::unique_ptr<octomap::OcTree> ChannelAsOcTree(const DualOcTree& tree, MapChannel channel) {
  auto plain = std::make_unique<BuildableOcTree>(tree.getResolution());
  plain->setOccupancyThres(tree.getOccupancyThres());
  plain->setClampingThresMin(tree.getClampingThresMin());
  plain->setClampingThresMax(tree.getClampingThresMax());
  if (tree.getRoot() != nullptr) {
    CopyChannelRecurs(tree, tree.getRoot(), *plain, plain->CreateRoot(), channel);
  }
  return plain;
}

robotio::Status ExportBinary(const DualOcTree& tree, MapChannel channel,
                             const std::string& file) {
  const std::unique_ptr<octomap::OcTree> plain = ChannelAsOcTree(tree, channel);
  std::ostringstream out(std::ios::binary);
  if (!plain->writeBinaryConst(out)) return robotio::Error{file + ": could not serialise the map"};
  return robotio::WriteFileAtomically(file, out.str());
}

}  // namespace dynamap::mapping
