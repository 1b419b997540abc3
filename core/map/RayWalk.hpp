#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include <Eigen/Core>

#include "map/DistanceField.hpp"

namespace unimap::map {

// Occupancy of one block of DistanceField::kBlockEdge^3 voxels, as a ray
// walk needs it.
struct BlockOccupancy {
  // Bit BlockOffset(x, y, z) set for each occupied voxel; null: none is.
  const std::array<std::uint64_t, DistanceField::kBlockCells / 64>* mask = nullptr;
  std::uint8_t quarters = 0;  // bit QuarterIndex set for each 4^3 quarter holding an occupied voxel
  // Bit set for each occupied voxel the walk is not to visit (already
  // settled by an earlier ray); null: every occupied voxel is visited.
  const std::array<std::uint64_t, DistanceField::kBlockCells / 64>* settled = nullptr;
};

// Blocks split into 2x2x2 quarters of 4^3 voxels, for rays to cross an
// empty quarter in one step.
inline constexpr int kQuarterShift = 2;
inline constexpr int kQuarterEdge = 1 << kQuarterShift;

// Index (0-7) of the quarter of its block holding the voxel key.
inline int QuarterIndex(const Eigen::Vector3i& key) {
  constexpr int kMask = DistanceField::kBlockEdge - 1;
  return (((key.x() & kMask) >> kQuarterShift) << 2) | (((key.y() & kMask) >> kQuarterShift) << 1) |
         ((key.z() & kMask) >> kQuarterShift);
}
// The quarters of a block holding a voxel of mask (BlockOccupancy::quarters).
std::uint8_t QuarterMask(const std::array<std::uint64_t, DistanceField::kBlockCells / 64>& mask);

// Amanatides & Woo's traversal in voxel-key units (voxel edges at integers)
// from origin_keys to the centre of voxel `end`, that voxel excluded,
// calling visit(key) for each occupied voxel it passes that is not settled
// (keys in the 16-bit range only). lookup(block_key) -> BlockOccupancy says what a block holds;
// blocks and quarters holding no occupied voxel (and not the end) are
// crossed in one step. visit returns true when it changed the occupancy:
// the walk then looks its block up again. Only empty space is skipped: a
// ray visits the voxels a voxel-by-voxel walk visits, except where it
// leaves a skipped cube exactly through a voxel edge or corner (a tie,
// e.g. a sensor at integer key coordinates): the walk resumes in the voxel
// past the tie and the voxels the ray only touches there are not visited
// (a voxel-by-voxel walk visits one of them, by its tie-breaking order).
template <class Lookup, class Visit>
void WalkRay(const Eigen::Vector3d& origin_keys, const Eigen::Vector3i& end, Lookup&& lookup, Visit&& visit) {
  constexpr int kEdge = DistanceField::kBlockEdge;
  const auto block_of = [](const Eigen::Vector3i& key) {
    return key.unaryExpr([](int v) { return v >> DistanceField::kBlockShift; }).eval();
  };
  const auto quarter_of = [](const Eigen::Vector3i& key) {
    return key.unaryExpr([](int v) { return v >> kQuarterShift; }).eval();
  };
  const Eigen::Vector3d direction = end.cast<double>() + Eigen::Vector3d::Constant(0.5) - origin_keys;
  Eigen::Vector3i current = origin_keys.array().floor().cast<int>();
  Eigen::Vector3i step;
  Eigen::Vector3d t_max, t_delta;
  // 1 / direction (0 where the ray is parallel to an axis: never used there).
  Eigen::Vector3d inverse = Eigen::Vector3d::Zero();
  for (int a = 0; a < 3; ++a) {
    if (direction[a] != 0.0) inverse[a] = 1.0 / direction[a];
  }
  for (int a = 0; a < 3; ++a) {
    step[a] = direction[a] > 0.0 ? 1 : -1;
    if (direction[a] == 0.0) {
      t_max[a] = t_delta[a] = std::numeric_limits<double>::infinity();
    } else {
      t_max[a] = (static_cast<double>(current[a] + (step[a] > 0 ? 1 : 0)) - origin_keys[a]) / direction[a];
      t_delta[a] = static_cast<double>(step[a]) / direction[a];
    }
  }
  Eigen::Vector3i cached_block = Eigen::Vector3i::Constant(-1);
  BlockOccupancy occupancy;
  double t = 0.0;  // ray parameter of the current voxel's entry
  // Moves the walk to where the ray leaves the cube of edge `edge` voxels
  // whose lowest voxel is `low`. kStuck: rounding left it inside the cube;
  // it steps voxel by voxel.
  enum class Leave { kEnded, kMoved, kStuck };
  const auto leave = [&](const Eigen::Vector3i& low, int edge) {
    double t_exit = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      if (direction[a] == 0.0) continue;
      const double face = static_cast<double>(low[a] + (step[a] > 0 ? edge : 0));
      t_exit = std::min(t_exit, (face - origin_keys[a]) * inverse[a]);
    }
    if (t_exit >= 1.0) return Leave::kEnded;
    const double t_next = std::max(t, t_exit);
    const Eigen::Vector3d position = origin_keys + (t_next + 1e-9) * direction;
    // floor(): truncation where it is the same (keys are non-negative), a
    // library call only outside the key range.
    const Eigen::Vector3i next =
        position.unaryExpr([](double v) { return v >= 0.0 ? static_cast<int>(v) : static_cast<int>(std::floor(v)); });
    if (((next - low).array() >= 0).all() && ((next - low).array() < edge).all()) return Leave::kStuck;
    t = t_next;
    current = next;
    for (int a = 0; a < 3; ++a) {
      if (direction[a] != 0.0) {
        t_max[a] = (static_cast<double>(current[a] + (step[a] > 0 ? 1 : 0)) - origin_keys[a]) * inverse[a];
      }
    }
    return Leave::kMoved;
  };
  // The walk stays between its two ends: when both are in the key range,
  // every voxel is.
  const auto in_range = [](const Eigen::Vector3i& key) {
    return (key.array() >= 0).all() && (key.array() <= 65535).all();  // 16-bit keys
  };
  const bool all_in_range = in_range(current) && in_range(end);
  while (current != end) {
    if (all_in_range || in_range(current)) {
      const Eigen::Vector3i block = block_of(current);
      if (block != cached_block) {
        cached_block = block;
        occupancy = lookup(block);
      }
      // Nothing occupied in this block, or in this quarter of it: jump to
      // where the ray leaves it (unless the return lies inside).
      Leave left = Leave::kStuck;
      if (occupancy.mask == nullptr && block_of(end) != block) {
        left = leave(block * kEdge, kEdge);
      } else if ((occupancy.quarters >> QuarterIndex(current) & 1u) == 0) {
        const Eigen::Vector3i quarter = quarter_of(current);
        if (quarter_of(end) != quarter) left = leave(quarter * kQuarterEdge, kQuarterEdge);
      }
      if (left == Leave::kEnded) break;
      if (left == Leave::kMoved) continue;
      const auto bit = static_cast<std::size_t>(
          DistanceField::BlockOffset(current.x() & (kEdge - 1), current.y() & (kEdge - 1), current.z() & (kEdge - 1)));
      if (occupancy.mask != nullptr && ((*occupancy.mask)[bit / 64] >> (bit % 64) & 1u) != 0 &&
          (occupancy.settled == nullptr || ((*occupancy.settled)[bit / 64] >> (bit % 64) & 1u) == 0) &&
          visit(current)) {
        cached_block = Eigen::Vector3i::Constant(-1);
      }
    }
    int axis = 0;
    if (t_max[1] < t_max[axis]) axis = 1;
    if (t_max[2] < t_max[axis]) axis = 2;
    if (t_max[axis] > 1.0) break;  // past the return (rounding at its voxel's boundary)
    t = t_max[axis];
    current[axis] += step[axis];
    t_max[axis] += t_delta[axis];
  }
}

}  // namespace unimap::map
