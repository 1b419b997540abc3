#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <tsl/robin_set.h>
#include <Eigen/Core>

namespace unimap::matching {

// A 64-bit key of a voxel cell (21 bits per axis, cells within +-2^20 of
// the origin are distinct): for hashing voxels.
inline std::uint64_t VoxelCellKey(const Eigen::Vector3i& cell) {
  const auto bits = [](int v) {
    return static_cast<std::uint64_t>(static_cast<std::int64_t>(v) + (1 << 20)) & 0x1FFFFF;
  };
  return (bits(cell.x()) << 42) | (bits(cell.y()) << 21) | bits(cell.z());
}

// The key of the cell (edge 1 / inv_voxel) holding p, as VoxelDownsample groups points.
std::uint64_t VoxelKey(const Eigen::Vector3f& p, double inv_voxel);

// Hash of VoxelCellKey / VoxelKey values for power-of-two tables: folds
// the three 21-bit fields together, then spreads them over the word
// (Fibonacci multiplier).
struct VoxelKeyHash {
  std::size_t operator()(std::uint64_t key) const {
    const std::uint64_t folded = (key ^ (key >> 21) ^ (key >> 42)) * 0x9E3779B97F4A7C15ull;
    return static_cast<std::size_t>(folded ^ (folded >> 32));
  }
};
// A set of such keys (open addressing).
using VoxelKeySet = tsl::robin_set<std::uint64_t, VoxelKeyHash>;

// Keeps one point per voxel (the first one seen, so the result is
// deterministic and a real measurement), then at most max_points of them
// chosen with a seeded generator (0 = keep all).
std::vector<Eigen::Vector3f> VoxelDownsample(const std::vector<Eigen::Vector3f>& points, double voxel_m, int max_points,
                                             std::uint64_t seed);

// The indices of the points VoxelDownsample(points, voxel_m, 0, 0) keeps
// (the first of each voxel), in order: to keep what goes with them.
std::vector<std::size_t> VoxelFirstIndices(const std::vector<Eigen::Vector3f>& points, double voxel_m);

// One point per voxel: the mean of the points in it, in the order the
// voxels are first seen (deterministic).
std::vector<Eigen::Vector3f> VoxelCentroids(const std::vector<Eigen::Vector3f>& points, double voxel_m);

}  // namespace unimap::matching
