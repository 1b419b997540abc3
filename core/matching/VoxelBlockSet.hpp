#pragma once
#include <array>
#include <cstddef>
#include <cstdint>

#include <tsl/robin_map.h>
#include <Eigen/Core>

#include "matching/VoxelDownsampler.hpp"

namespace unimap::matching {

// A set of voxel cells kept as 8 x 8 x 8 blocks of bits. Surfaces fill the
// blocks they cross, so a cell costs about a bit plus its block's share
// (about 160 bytes a block) instead of the 32 bytes a cell that a hash set
// of keys costs at its load factor, and the table grows by blocks, not by
// cells (docs/reliability.md, memory over long runs). Cells within +-2^23
// of the origin are distinct (VoxelCellKey of the block). Not thread-safe.
class VoxelBlockSet {
 public:
  // Adds cell; true when the set did not hold it yet.
  bool Insert(const Eigen::Vector3i& cell);
  // Whether the set holds cell.
  bool Contains(const Eigen::Vector3i& cell) const;
  std::size_t size() const { return size_; }                  // cells held
  std::size_t block_count() const { return blocks_.size(); }  // blocks with a cell
  std::size_t MemoryBytes() const;                            // approximate footprint of the table (bytes)

 private:
  using Mask = std::array<std::uint64_t, 8>;  // bit (y & 7) * 8 + (z & 7) of word (x & 7)
  tsl::robin_map<std::uint64_t, Mask, VoxelKeyHash> blocks_;
  std::size_t size_ = 0;
};

}  // namespace unimap::matching
