#include "ScanBlocks.hpp"

namespace dynamap::mapping {
namespace {

constexpr std::size_t kMaxDenseCells = std::size_t{1} << 22;

std::uint64_t Interleave13(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  std::uint64_t code = 0;
  for (int bit = 12; bit >= 0; --bit) {
    code = (code << 3) | ((x >> bit) & 1u) | (((y >> bit) & 1u) << 1) | (((z >> bit) & 1u) << 2);
  }
  return code;
}

// Bits 0, 3, 6 of v gathered into bits 0, 1, 2 (Spread3 undone).
constexpr std::uint32_t Gather3(std::uint32_t v) {
  return (v & 1u) | ((v >> 2) & 2u) | ((v >> 4) & 4u);
}

std::uint64_t BlockId(std::uint32_t bx, std::uint32_t by, std::uint32_t bz) {
  return (std::uint64_t{bx} << 32) | (std::uint64_t{by} << 16) | bz;
}

}  // namespace

octomap::OcTreeKey KeyOfBit(const ScanBlock& block, std::uint32_t bit) {
  return octomap::OcTreeKey(
      static_cast<octomap::key_type>((block.coords[0] << 3) | Gather3(bit)),
      static_cast<octomap::key_type>((block.coords[1] << 3) | Gather3(bit >> 1)),
      static_cast<octomap::key_type>((block.coords[2] << 3) | Gather3(bit >> 2)));
}

void ScanBlocks::Reset(const octomap::OcTreeKey& min_key, const octomap::OcTreeKey& max_key) {
  blocks_.clear();
  last_slot_ = -1;
  last_block_id_ = ~0ull;
  std::size_t cells = 1;
  for (int a = 0; a < 3; ++a) {
    box_min_[a] = static_cast<std::uint16_t>(min_key[a] >> 3);
    box_dims_[a] = static_cast<std::uint32_t>((max_key[a] >> 3) - box_min_[a] + 1);
    cells *= box_dims_[a];
  }
  use_dense_ = cells <= kMaxDenseCells;
  if (use_dense_) {
    dense_index_.assign(cells, -1);
  } else {
    sparse_index_.clear();
  }
}

std::int32_t& ScanBlocks::SlotOf(std::uint32_t bx, std::uint32_t by, std::uint32_t bz) {
  if (!use_dense_) return sparse_index_.try_emplace(BlockId(bx, by, bz), -1).first->second;
  const std::size_t cell =
      (static_cast<std::size_t>(bz - box_min_[2]) * box_dims_[1] + (by - box_min_[1])) *
          box_dims_[0] +
      (bx - box_min_[0]);
  return dense_index_[cell];
}

ScanBlock& ScanBlocks::BlockFor(const octomap::OcTreeKey& key) {
  const std::uint32_t bx = key[0] >> 3, by = key[1] >> 3, bz = key[2] >> 3;
  const std::uint64_t id = BlockId(bx, by, bz);
  if (id == last_block_id_) return blocks_[static_cast<std::size_t>(last_slot_)];
  std::int32_t& slot = SlotOf(bx, by, bz);
  if (slot < 0) {
    slot = static_cast<std::int32_t>(blocks_.size());
    ScanBlock& block = blocks_.emplace_back();
    block.coords[0] = static_cast<std::uint16_t>(bx);
    block.coords[1] = static_cast<std::uint16_t>(by);
    block.coords[2] = static_cast<std::uint16_t>(bz);
    block.morton = Interleave13(bx, by, bz);
  }
  last_block_id_ = id;
  last_slot_ = slot;
  return blocks_[static_cast<std::size_t>(slot)];
}

ScanBlock* ScanBlocks::FindBlock(const octomap::OcTreeKey& key) {
  const std::uint32_t bx = key[0] >> 3, by = key[1] >> 3, bz = key[2] >> 3;
  std::int32_t slot = -1;
  if (use_dense_) {
    if (bx < box_min_[0] || by < box_min_[1] || bz < box_min_[2]) return nullptr;
    const std::uint32_t cx = bx - box_min_[0], cy = by - box_min_[1], cz = bz - box_min_[2];
    if (cx >= box_dims_[0] || cy >= box_dims_[1] || cz >= box_dims_[2]) return nullptr;
    slot = dense_index_[(static_cast<std::size_t>(cz) * box_dims_[1] + cy) * box_dims_[0] + cx];
  } else {
    const auto it = sparse_index_.find(BlockId(bx, by, bz));
    if (it != sparse_index_.end()) slot = it->second;
  }
  return slot < 0 ? nullptr : &blocks_[static_cast<std::size_t>(slot)];
}

void ScanBlocks::Merge(const ScanBlocks& other) {
  for (const ScanBlock& theirs : other.blocks_) {
    const octomap::OcTreeKey key(static_cast<octomap::key_type>(theirs.coords[0] << 3),
                                 static_cast<octomap::key_type>(theirs.coords[1] << 3),
                                 static_cast<octomap::key_type>(theirs.coords[2] << 3));
    ScanBlock& ours = BlockFor(key);
    for (int w = 0; w < 8; ++w) {
      ours.free[w] |= theirs.free[w];
      ours.hit[w] |= theirs.hit[w];
    }
  }
}

}  // namespace dynamap::mapping
