// One OctoMap tree whose nodes hold a static and a dynamic log-odds value (thesis 4.2-4.3,
// Wolf & Sukhatme 2005 in 3D), built like OctoMap's ColorOcTree and registered for .ot.
#pragma once

#include <memory>

#include <octomap/OccupancyOcTreeBase.h>
#include <octomap/OcTreeNode.h>

#include <iosfwd>
#include <string>

namespace dynamap::mapping {

class DualOcTree;

// `value` (inherited) is the static log-odds, so every OctoMap algorithm that reads
// occupancy (ray casting, iterators, .bt export) sees the static map.
class DualOcTreeNode : public octomap::OcTreeNode {
 public:
  friend class DualOcTree;

  DualOcTreeNode() = default;
  DualOcTreeNode(const DualOcTreeNode& rhs) = default;
  DualOcTreeNode& operator=(const DualOcTreeNode& rhs) = delete;

  // Both channels: pruning compares nodes with this, so eight children only collapse when
  // they agree on both the static and the dynamic value.
  bool operator==(const DualOcTreeNode& rhs) const {
    return rhs.value == value && rhs.dynamic_log_odds_ == dynamic_log_odds_;
  }
  // Used by OctoMap's expandNode/pruneNode: a pruned parent hands both channels on.
  void copyData(const DualOcTreeNode& from) {
    octomap::OcTreeNode::copyData(from);
    dynamic_log_odds_ = from.dynamic_log_odds_;
  }

  [[nodiscard]] float StaticLogOdds() const { return value; }
  [[nodiscard]] float DynamicLogOdds() const { return dynamic_log_odds_; }
  void SetStaticLogOdds(float l) { value = l; }
  void SetDynamicLogOdds(float l) { dynamic_log_odds_ = l; }

  // Inner nodes hold the maximum of their children in each channel (OctoMap's
  // conservative rule). Hides OcTreeNode's version: OctoMap's templates call it on NODE.
  void updateOccupancyChildren();
  [[nodiscard]] float MaxChildDynamicLogOdds() const;

  // .ot payload: static float, then dynamic float.
  std::istream& readData(std::istream& s);
  std::ostream& writeData(std::ostream& s) const;

 private:
  float dynamic_log_odds_ = 0.0f;
};

class DualOcTree : public octomap::OccupancyOcTreeBase<DualOcTreeNode> {
 public:
  // The type name in .ot headers.
  static constexpr const char* kTreeType = "DynamapDualOcTree";

  explicit DualOcTree(double resolution);
  DualOcTree* create() const override { return new DualOcTree(resolution); }
  std::string getTreeType() const override { return kTreeType; }

  // A deep copy with both channels and the sensor model (OctoMap's own copy constructor
  // copies inner nodes as its base node type, losing the dynamic channel).
  [[nodiscard]] std::unique_ptr<DualOcTree> Clone() const;

  // Node access for the batched scan update (ScanIntegrator), which walks the tree itself.
  [[nodiscard]] DualOcTreeNode* MutableRoot() { return root; }
  DualOcTreeNode* CreateRoot();

  // Occupancy in either channel with the tree's occupancy threshold.
  [[nodiscard]] bool IsStaticOccupied(const DualOcTreeNode& node) const {
    return node.StaticLogOdds() >= occ_prob_thres_log;
  }
  [[nodiscard]] bool IsDynamicOccupied(const DualOcTreeNode& node) const {
    return node.DynamicLogOdds() >= occ_prob_thres_log;
  }

 private:
  // Registers the type with OctoMap's .ot factory once per program (as ColorOcTree does);
  // the constructor touches it so a static link keeps the registration.
  class StaticMemberInitializer {
   public:
    StaticMemberInitializer();
    void EnsureLinking() {}
  };
  static StaticMemberInitializer registration_;
};

}  // namespace dynamap::mapping
