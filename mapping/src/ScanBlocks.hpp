// The voxels one scan observes, as bits in 8x8x8-voxel blocks over the scan's key box:
// ScanIntegrator's per-scan deduplication without hashing per ray step. Each thread fills
// a set of its own; the sets merge with OR.
#pragma once

// OctoMap's OcTreeKey.h uses uint16_t without including <cstdint>: keep this order.
// clang-format off
#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include <octomap/OcTreeKey.h>
// clang-format on

namespace dynamap::mapping {

struct ScanBlock {
  std::uint64_t morton = 0;             // Block coordinates interleaved: depth-first tree order.
  std::uint16_t coords[3] = {0, 0, 0};  // key >> 3 per axis.
  std::uint64_t free[8] = {};           // Bit (Morton index within block) per voxel.
  std::uint64_t hit[8] = {};
  std::uint64_t end[8] = {};  // End voxel already queued for tracing.
};

// Spreads the 3 low bits of v to bits 0, 3, 6.
constexpr std::uint32_t Spread3(std::uint32_t v) {
  return (v & 1u) | ((v & 2u) << 2) | ((v & 4u) << 4);
}

// Morton index of a voxel inside its block; the top 3 bits are the child index at depth
// 14, as octomap::computeChildIdx orders them (x = 1, y = 2, z = 4).
inline std::uint32_t InBlockIndex(const octomap::OcTreeKey& key) {
  return Spread3(key[0] & 7u) | (Spread3(key[1] & 7u) << 1) | (Spread3(key[2] & 7u) << 2);
}

// Sets voxel `key`'s bit in `words`; says whether it was clear.
inline bool SetBit(std::uint64_t (&words)[8], const octomap::OcTreeKey& key) {
  const std::uint32_t bit = InBlockIndex(key);
  const std::uint64_t mask = std::uint64_t{1} << (bit & 63u);
  const bool was_clear = (words[bit >> 6] & mask) == 0;
  words[bit >> 6] |= mask;
  return was_clear;
}

inline void ClearBit(std::uint64_t (&words)[8], const octomap::OcTreeKey& key) {
  const std::uint32_t bit = InBlockIndex(key);
  words[bit >> 6] &= ~(std::uint64_t{1} << (bit & 63u));
}

// The key of bit `bit` (InBlockIndex) of `block`.
[[nodiscard]] octomap::OcTreeKey KeyOfBit(const ScanBlock& block, std::uint32_t bit);

class ScanBlocks {
 public:
  // Empties the set for a scan whose keys all lie in [min_key, max_key].
  void Reset(const octomap::OcTreeKey& min_key, const octomap::OcTreeKey& max_key);
  ScanBlock& BlockFor(const octomap::OcTreeKey& key);
  // nullptr when the scan has no such block.
  [[nodiscard]] ScanBlock* FindBlock(const octomap::OcTreeKey& key);
  // ORs the free and hit bits of `other` (reset with the same box) into this set.
  void Merge(const ScanBlocks& other);

  [[nodiscard]] const std::vector<ScanBlock>& blocks() const { return blocks_; }

 private:
  std::int32_t& SlotOf(std::uint32_t bx, std::uint32_t by, std::uint32_t bz);

  std::vector<ScanBlock> blocks_;
  std::vector<std::int32_t> dense_index_;  // Block slot per block cell of the scan's box.
  std::unordered_map<std::uint64_t, std::int32_t> sparse_index_;  // When the box is huge.
  bool use_dense_ = true;
  std::uint16_t box_min_[3] = {0, 0, 0};
  std::uint32_t box_dims_[3] = {0, 0, 0};
  std::int32_t last_slot_ = -1;
  std::uint64_t last_block_id_ = ~0ull;
};

}  // namespace dynamap::mapping
