#include "map/RayWalk.hpp"

namespace unimap::map {

std::uint8_t QuarterMask(const std::array<std::uint64_t, DistanceField::kBlockCells / 64>& mask) {
  static_assert(DistanceField::kBlockEdge == 8, "quarters assume 8^3 blocks");
  // Word x of the mask holds the voxels of slice x (bit y * 8 + z, see
  // DistanceField::BlockOffset); these are the (y, z) quarters 00, 01, 10, 11.
  constexpr std::uint64_t kYz[4] = {0x000000000F0F0F0Full, 0x00000000F0F0F0F0ull, 0x0F0F0F0F00000000ull,
                                    0xF0F0F0F000000000ull};
  const std::uint64_t low = mask[0] | mask[1] | mask[2] | mask[3];
  const std::uint64_t high = mask[4] | mask[5] | mask[6] | mask[7];
  std::uint8_t out = 0;
  for (int yz = 0; yz < 4; ++yz) {
    if ((low & kYz[yz]) != 0) out |= static_cast<std::uint8_t>(1u << yz);
    if ((high & kYz[yz]) != 0) out |= static_cast<std::uint8_t>(1u << (4 + yz));
  }
  return out;
}

}  // namespace unimap::map
