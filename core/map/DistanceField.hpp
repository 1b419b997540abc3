#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "map/CellPlanes.hpp"

namespace unimap::map {

// Immutable snapshot of the distance map for lookups: a grid over an
// axis-aligned box, aligned with the map's voxels, holding for every voxel
// the distance from its centre to the nearest surface (the nearest occupied
// voxel centre, or that voxel's sub-voxel surface, see SurfacePoints),
// clamped at clamp(). Cells are stored in blocks of kBlockEdge^3 (a block
// grid over the box); a block whose cells all read clamp() is not stored,
// so memory follows the surfaces, not the box, and successive snapshots of
// a growing map share the blocks that did not change (SurfaceDistanceMap).
// Distances are stored in 16 bits: kUnsigned as steps of clamp() / 65535;
// kSigned as a distance in [-clamp(), clamp()] in 15 bits (steps of
// 2 clamp() / 32767), negative behind a surface, bit 0 flagging the cell's
// trilinear stencil (see kMaxCrossingSum). Lookups always return magnitudes
// (>= 0): signs only let the trilinear interpolation cross zero on a surface
// between two cell centres. Anything outside the box (and NaN) reads
// clamp(). Safe to share between threads: nothing changes after
// construction.
class DistanceField {
 public:
  // Largest quantised value; stands for clamp().
  static constexpr std::uint16_t kMaxSteps = 65535;
  // Cells per block edge (a power of two) and per block.
  static constexpr int kBlockShift = 3;
  static constexpr int kBlockEdge = 1 << kBlockShift;
  static constexpr int kBlockCells = kBlockEdge * kBlockEdge * kBlockEdge;
  // One block's codes; the cell at (x, y, z) within it is at BlockOffset(x, y, z).
  using Block = std::vector<std::uint16_t>;
  static constexpr int BlockOffset(int x, int y, int z) { return (x << (2 * kBlockShift)) | (y << kBlockShift) | z; }
  // Largest 15-bit kSigned value; stands for +clamp() (0 for -clamp()).
  static constexpr std::uint16_t kMaxSignedSteps = 32767;
  // How cells encode distances.
  enum class Encoding {
    kUnsigned,  // code = Quantise(distance): distance = code * clamp / 65535
    kSigned,    // code = QuantiseSigned(s): s = (code >> 1) * 2 clamp / 32767 - clamp;
                // the constructor sets bit 0 (the stencil flag)
  };
  // Signed fields: the trilinear interpolation may cross zero along a cell
  // edge whose end values have opposite signs only when their magnitudes sum
  // to at most this many cell edges (a surface between them); otherwise the
  // sign change is where the two sides of a surface's edge meet, not a
  // surface. A stencil with such an edge (or any edge whose values differ by
  // more) interpolates magnitudes; the constructor flags the stencils (by
  // their lowest cell) once, so lookups test one bit.
  static constexpr float kMaxCrossingSum = 1.25f;

  // An empty field: every lookup returns clamp_m.
  explicit DistanceField(float clamp_m, std::uint64_t sequence = 0);
  // A field over the box [origin_m, origin_m + dims * resolution_m) with
  // cells[(ix * dims.y() + iy) * dims.z() + iz] = Quantise(distance of cell).
  // Throws unimap::InputError when the sizes disagree or a value is invalid.
  DistanceField(const Eigen::Vector3f& origin_m, const Eigen::Vector3i& dims, float resolution_m, float clamp_m,
                std::vector<std::uint16_t> cells, std::uint64_t sequence);
  // The same with cells in the given encoding.
  DistanceField(const Eigen::Vector3f& origin_m, const Eigen::Vector3i& dims, float resolution_m, float clamp_m,
                std::vector<std::uint16_t> cells, std::uint64_t sequence, Encoding encoding);
  // A kUnsigned field over block_dims blocks from origin_m, blocks[(bx *
  // block_dims.y() + by) * block_dims.z() + bz] each kBlockCells codes or
  // null (every cell reads clamp). Throws unimap::InputError when the sizes
  // disagree or a value is invalid.
  DistanceField(const Eigen::Vector3f& origin_m, const Eigen::Vector3i& block_dims, float resolution_m, float clamp_m,
                std::vector<std::shared_ptr<const Block>> blocks, std::uint64_t sequence);

  // The 16-bit code of a distance (values >= clamp_m map to kMaxSteps).
  // Inline: the map's export calls it for every recomputed cell.
  static std::uint16_t Quantise(float distance_m, float clamp_m) {
    if (!(distance_m < clamp_m)) return kMaxSteps;  // also NaN
    if (distance_m <= 0.0f) return 0;
    // Round half up (the value is positive): cheaper than std::round in export loops.
    const float steps = distance_m / clamp_m * static_cast<float>(kMaxSteps) + 0.5f;
    return static_cast<std::uint16_t>(std::min(steps, static_cast<float>(kMaxSteps)));
  }
  // The kSigned code of a signed distance: 15 bits shifted left, bit 0
  // clear (saturates at +-clamp_m; NaN maps to +clamp_m).
  static std::uint16_t QuantiseSigned(float signed_distance_m, float clamp_m) {
    if (std::isnan(signed_distance_m)) return static_cast<std::uint16_t>(kMaxSignedSteps << 1);
    const float unit = std::clamp(signed_distance_m / clamp_m, -1.0f, 1.0f);  // [-1, 1]
    // Round half up (the value is >= 0): cheaper than std::round in export loops.
    const auto steps = static_cast<std::uint16_t>((unit + 1.0f) * (0.5f * static_cast<float>(kMaxSignedSteps)) + 0.5f);
    return static_cast<std::uint16_t>(steps << 1);
  }

  // Distance (m) of the voxel containing p_map; clamp() outside the box.
  // One floor per axis, one index, one load.
  float Distance(const Eigen::Vector3f& p_map) const {
    const float fx = (p_map.x() - origin_m_.x()) * inv_resolution_;
    const float fy = (p_map.y() - origin_m_.y()) * inv_resolution_;
    const float fz = (p_map.z() - origin_m_.z()) * inv_resolution_;
    if (!(fx >= 0.0f && fy >= 0.0f && fz >= 0.0f && fx < dims_f_.x() && fy < dims_f_.y() && fz < dims_f_.z())) {
      return clamp_m_;
    }
    const Block* block = BlockAt(static_cast<int>(fx), static_cast<int>(fy), static_cast<int>(fz));
    if (block == nullptr) return clamp_m_;
    const std::uint16_t code = (*block)[static_cast<std::size_t>(BlockOffset(
        static_cast<int>(fx) & kBlockMask, static_cast<int>(fy) & kBlockMask, static_cast<int>(fz) & kBlockMask))];
    return std::abs(static_cast<float>(code >> shift_) * step_m_ - offset_m_);
  }

  // Trilinear interpolation between voxel centres (cells outside the box
  // count as clamp()); *gradient_map (if not null) receives its gradient.
  // Signed fields interpolate the signed values and return the magnitude
  // (see kMaxCrossingSum), so a surface between two centres reads zero.
  float DistanceTrilinear(const Eigen::Vector3f& p_map, Eigen::Vector3f* gradient_map) const;
  // out[i] = DistanceTrilinear(points_map[i], nullptr) for i < n, the same
  // values; faster when the points fall in a few neighbouring stencils, in
  // any order (the particles of one scan point).
  void DistancesTrilinear(const Eigen::Vector3f* points_map, int n, float* out) const;

  // Attaches the planes of the cells' nearest surface elements (same grid);
  // call before the field is shared. Throws InputError when the sizes differ.
  void SetPlanes(CellPlanes planes);
  // The plane of the surface element nearest to the cell containing p_map:
  // unit normal and offset with normal . x + offset the signed height of x
  // above it. False outside the box, without planes, or when the cell has none.
  bool PlaneAt(const Eigen::Vector3f& p_map, Eigen::Vector3f* normal, float* offset_m) const;
  bool HasPlanes() const { return planes_.size() > 0; }

  // Distance (m) stored for a cell; clamp() when the cell is outside the grid.
  float CellDistance(const Eigen::Vector3i& cell) const;
  // Signed value (m) stored for a cell (negative behind a surface in kSigned
  // fields; equals CellDistance in kUnsigned ones); clamp() outside the grid.
  float CellValue(const Eigen::Vector3i& cell) const;
  // Centre of a cell in the map frame.
  Eigen::Vector3f CellCenter(const Eigen::Vector3i& cell) const;
  // True when p_map lies inside the box.
  bool Contains(const Eigen::Vector3f& p_map) const;

  const Eigen::Vector3f& origin() const { return origin_m_; }  // box min corner (m)
  Eigen::Vector3f box_max() const;                             // box max corner (m)
  const Eigen::Vector3i& dims() const { return dims_; }        // cells per axis
  float resolution() const { return resolution_m_; }           // cell edge (m)
  float clamp() const { return clamp_m_; }                     // clamp distance (m)
  Encoding encoding() const { return offset_m_ > 0.0f ? Encoding::kSigned : Encoding::kUnsigned; }
  std::uint64_t sequence() const { return sequence_; }  // updates integrated when exported
  // Cells of the box (stored or not).
  std::size_t CellCount() const {
    return static_cast<std::size_t>(dims_.x()) * static_cast<std::size_t>(dims_.y()) *
           static_cast<std::size_t>(dims_.z());
  }
  // Blocks stored (holding a cell below the clamp).
  std::size_t StoredBlocks() const;
  // Calls visit(cell) for every cell of the box whose distance is at most
  // max_distance_m (< clamp()), block by block.
  void ForEachCellWithin(float max_distance_m, const std::function<void(const Eigen::Vector3i&)>& visit) const;
  std::size_t MemoryBytes() const {
    return StoredBlocks() * kBlockCells * sizeof(std::uint16_t) +
           blocks_.size() * sizeof(std::shared_ptr<const Block>) + planes_.MemoryBytes();
  }

 private:
  static constexpr int kBlockMask = kBlockEdge - 1;
  // Index of an in-grid cell in planes_ (x-y-z order over dims_).
  std::size_t CellIndex(const Eigen::Vector3i& cell) const {
    return static_cast<std::size_t>(cell.x()) * stride_x_ + static_cast<std::size_t>(cell.y()) * stride_y_ +
           static_cast<std::size_t>(cell.z());
  }
  // The block holding in-grid cell (x, y, z), or null when it is not stored.
  const Block* BlockAt(int x, int y, int z) const {
    return blocks_[static_cast<std::size_t>(x >> kBlockShift) * block_stride_x_ +
                   static_cast<std::size_t>(y >> kBlockShift) * block_stride_y_ +
                   static_cast<std::size_t>(z >> kBlockShift)]
        .get();
  }
  // The code of an in-grid cell (the clamp's code when its block is not stored).
  std::uint16_t Code(int x, int y, int z) const {
    const Block* block = BlockAt(x, y, z);
    return block == nullptr
               ? clamp_code_
               : (*block)[static_cast<std::size_t>(BlockOffset(x & kBlockMask, y & kBlockMask, z & kBlockMask))];
  }
  // The eight values of the in-box stencil at (ix, iy, iz) (magnitudes where
  // FlagJumpingStencils flagged it); false when its single block is not
  // stored (every value the clamp).
  bool InBoxStencil(int ix, int iy, int iz, float* c) const;
  // Splits dense x-y-z cells into blocks (all-clamp blocks not stored).
  void StoreBlocks(const std::vector<std::uint16_t>& cells);

  Eigen::Vector3f origin_m_ = Eigen::Vector3f::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  Eigen::Vector3f dims_f_ = Eigen::Vector3f::Zero();  // dims_ as float, for the bounds test
  float resolution_m_ = 1.0f;
  float inv_resolution_ = 1.0f;
  float clamp_m_ = 0.0f;
  float step_m_ = 0.0f;          // metres per quantisation step
  float offset_m_ = 0.0f;        // value = (code >> shift_) * step_m_ - offset_m_
  int shift_ = 0;                // 1 when signed (bit 0 is the stencil flag)
  std::uint16_t flag_mask_ = 0;  // 1 when signed: the stencil flag
  float max_crossing_m_ = 0.0f;  // kMaxCrossingSum * resolution_m_
  std::size_t stride_x_ = 0;     // x-y-z order over dims_ (planes_)
  std::size_t stride_y_ = 0;
  Eigen::Vector3i block_dims_ = Eigen::Vector3i::Zero();  // blocks per axis
  std::size_t block_stride_x_ = 0;
  std::size_t block_stride_y_ = 0;
  std::uint16_t clamp_code_ = kMaxSteps;  // the code every cell of a missing block reads
  std::vector<std::shared_ptr<const Block>> blocks_;
  CellPlanes planes_;  // SetPlanes's; empty: none
  std::uint64_t sequence_ = 0;

  // Sets the stencil flag of every cell of the dense x-y-z cells whose
  // stencil (itself up to +1 on every axis, all inside) has an edge whose
  // values differ by more than max_crossing_m_ (kSigned only).
  void FlagJumpingStencils(std::vector<std::uint16_t>* cells) const;
};

}  // namespace unimap::map
