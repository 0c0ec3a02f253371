#include "dynamap/mapping/DualOcTree.hpp"

#include <algorithm>
#include <istream>
#include <limits>
#include <ostream>

namespace dynamap::mapping {

void DualOcTreeNode::updateOccupancyChildren() {
  setLogOdds(getMaxChildLogOdds());
  dynamic_log_odds_ = MaxChildDynamicLogOdds();
}

float DualOcTreeNode::MaxChildDynamicLogOdds() const {
  float max = -std::numeric_limits<float>::max();
  if (children == nullptr) return max;
  for (unsigned int i = 0; i < 8; ++i) {
    if (children[i] != nullptr) {
      max = std::max(max, static_cast<const DualOcTreeNode*>(children[i])->dynamic_log_odds_);
    }
  }
  return max;
}

std::istream& DualOcTreeNode::readData(std::istream& s) {
  s.read(reinterpret_cast<char*>(&value), sizeof(value));
  s.read(reinterpret_cast<char*>(&dynamic_log_odds_), sizeof(dynamic_log_odds_));
  return s;
}

std::ostream& DualOcTreeNode::writeData(std::ostream& s) const {
  s.write(reinterpret_cast<const char*>(&value), sizeof(value));
  s.write(reinterpret_cast<const char*>(&dynamic_log_odds_), sizeof(dynamic_log_odds_));
  return s;
}

DualOcTree::DualOcTree(double resolution)
    : octomap::OccupancyOcTreeBase<DualOcTreeNode>(resolution) {
  registration_.EnsureLinking();
}

namespace {

void CopyChildren(const DualOcTree& from_tree, const DualOcTreeNode& from, DualOcTree& to_tree,
                  DualOcTreeNode* to) {
  for (unsigned int i = 0; i < 8; ++i) {
    if (!from_tree.nodeChildExists(&from, i)) continue;
    const DualOcTreeNode* child = from_tree.getNodeChild(&from, i);
    DualOcTreeNode* copy = to_tree.createNodeChild(to, i);
    copy->copyData(*child);
    CopyChildren(from_tree, *child, to_tree, copy);
  }
}

}  // namespace

std::unique_ptr<DualOcTree> DualOcTree::Clone() const {
  auto copy = std::make_unique<DualOcTree>(resolution);
  copy->setOccupancyThres(getOccupancyThres());
  copy->setProbHit(getProbHit());
  copy->setProbMiss(getProbMiss());
  copy->setClampingThresMin(getClampingThresMin());
  copy->setClampingThresMax(getClampingThresMax());
  if (root != nullptr) {
    DualOcTreeNode* copy_root = copy->CreateRoot();
    copy_root->copyData(*root);
    CopyChildren(*this, *root, *copy, copy_root);
  }
  return copy;
}

DualOcTreeNode* DualOcTree::CreateRoot() {
  if (root == nullptr) {
    root = new DualOcTreeNode();
    ++tree_size;
    size_changed = true;
  }
  return root;
}

DualOcTree::StaticMemberInitializer::StaticMemberInitializer() {
  auto* prototype = new DualOcTree(0.1);
  prototype->clearKeyRays();
  octomap::AbstractOcTree::registerTreeType(prototype);
}

DualOcTree::StaticMemberInitializer DualOcTree::registration_;

}  // namespace dynamap::mapping
