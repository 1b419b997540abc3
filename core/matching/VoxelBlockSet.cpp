#include "matching/VoxelBlockSet.hpp"

namespace unimap::matching {

namespace {

constexpr int kShift = 3;  // 8 cells a block edge
constexpr int kLast = (1 << kShift) - 1;

std::uint64_t BlockKey(const Eigen::Vector3i& cell) {
  // Arithmetic shifts floor negative cells into their block.
  return VoxelCellKey(Eigen::Vector3i(cell.x() >> kShift, cell.y() >> kShift, cell.z() >> kShift));
}

std::uint64_t Bit(const Eigen::Vector3i& cell) {
  return std::uint64_t{1} << (((cell.y() & kLast) << kShift) | (cell.z() & kLast));
}

}  // namespace

bool VoxelBlockSet::Insert(const Eigen::Vector3i& cell) {
  Mask& mask = blocks_.try_emplace(BlockKey(cell), Mask{}).first.value();
  std::uint64_t& word = mask[static_cast<std::size_t>(cell.x() & kLast)];
  const std::uint64_t bit = Bit(cell);
  if ((word & bit) != 0) return false;
  word |= bit;
  ++size_;
  return true;
}

bool VoxelBlockSet::Contains(const Eigen::Vector3i& cell) const {
  const auto it = blocks_.find(BlockKey(cell));
  return it != blocks_.end() && (it->second[static_cast<std::size_t>(cell.x() & kLast)] & Bit(cell)) != 0;
}

std::size_t VoxelBlockSet::MemoryBytes() const {
  return sizeof(*this) + blocks_.bucket_count() * (sizeof(std::uint64_t) + sizeof(Mask) + sizeof(std::int16_t) * 4);
}

}  // namespace unimap::matching
