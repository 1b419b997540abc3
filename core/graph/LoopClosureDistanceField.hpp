#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace unimap::graph {

// Fine distance field of a submap, used to refine and score loop closures:
// per cell of edge resolution_m, the Euclidean distance from the cell centre
// to the nearest submap point, exact up to clamp_m and stored in 8-bit steps
// of clamp_m / 255, and that point itself with its surface normal
// (LoopClosureNormals), for point-to-plane residuals (an interpolated
// unsigned distance has its minimum at the cell centre nearest a surface,
// not on it, which would bias the pose by up to half a cell). Only blocks of
// 8^3 cells within clamp_m of a point are stored (a dense block index over
// the box), so memory follows the surface area, not the box volume.
// Everything else reads clamp_m / no point. Immutable after construction;
// safe to share between threads.
class LoopClosureDistanceField {
 public:
  static constexpr int kBlockShift = 3;  // blocks of 2^3 = 8 cells per axis
  static constexpr int kBlockEdge = 1 << kBlockShift;
  static constexpr int kBlockCells = kBlockEdge * kBlockEdge * kBlockEdge;
  // Largest number of blocks in the dense block index; more is an InputError.
  static constexpr std::size_t kMaxIndexBlocks = std::size_t{1} << 27;

  // Builds the field from submap points (submap frame, all finite, at least
  // one); resolution_m > 0, clamp_m >= resolution_m; normals as
  // LoopClosureNormals(points, normal_cell_m, planarity_ratio). Throws
  // unimap::InputError when the box needs more than kMaxIndexBlocks blocks.
  LoopClosureDistanceField(const std::vector<Eigen::Vector3f>& points_submap, double resolution_m, double clamp_m,
                           double normal_cell_m, double planarity_ratio);

  // The submap point nearest to the centre of the cell containing p, and its
  // unit normal (zero when its neighbourhood spans no plane); false when no
  // point lies within clamp() of that centre.
  bool NearestPoint(const Eigen::Vector3f& p_submap, Eigen::Vector3f* point, Eigen::Vector3f* normal) const {
    const Eigen::Vector3f f = (p_submap - origin_m_) * inv_resolution_;
    if (!(f.x() >= 0.0f && f.y() >= 0.0f && f.z() >= 0.0f && f.x() < static_cast<float>(dims_.x()) &&
          f.y() < static_cast<float>(dims_.y()) && f.z() < static_cast<float>(dims_.z()))) {
      return false;
    }
    const int x = static_cast<int>(f.x());
    const int y = static_cast<int>(f.y());
    const int z = static_cast<int>(f.z());
    const std::int32_t block = block_index_[BlockSlot(x >> kBlockShift, y >> kBlockShift, z >> kBlockShift)];
    if (block < 0) return false;
    const std::int32_t nearest = nearest_[static_cast<std::size_t>(block) * kBlockCells + LocalIndex(x, y, z)];
    if (nearest < 0) return false;
    *point = points_[static_cast<std::size_t>(nearest)];
    *normal = normals_[static_cast<std::size_t>(nearest)];
    return true;
  }

  // Stored distance of a cell (m); clamp() outside the stored blocks.
  float CellDistance(int x, int y, int z) const {
    if (x < 0 || y < 0 || z < 0 || x >= dims_.x() || y >= dims_.y() || z >= dims_.z()) return clamp_m_;
    const std::int32_t block = block_index_[BlockSlot(x >> kBlockShift, y >> kBlockShift, z >> kBlockShift)];
    if (block < 0) return clamp_m_;
    return static_cast<float>(cells_[static_cast<std::size_t>(block) * kBlockCells + LocalIndex(x, y, z)]) * step_m_;
  }
  // Trilinear interpolation between cell centres (m); *gradient_submap (if
  // not null) receives its gradient (zero where every corner is clamped).
  float Distance(const Eigen::Vector3f& p_submap, Eigen::Vector3f* gradient_submap) const;

  float resolution() const { return resolution_m_; }                      // cell edge (m)
  float clamp() const { return clamp_m_; }                                // largest stored distance (m)
  const Eigen::Vector3f& origin() const { return origin_m_; }             // min corner of cell (0, 0, 0) (m)
  std::size_t BlockCount() const { return cells_.size() / kBlockCells; }  // stored blocks
  std::size_t MemoryBytes() const {                                       // bytes held (cells, points, block index)
    return cells_.size() + (nearest_.size() + block_index_.size()) * sizeof(std::int32_t) +
           (points_.size() + normals_.size()) * sizeof(Eigen::Vector3f);
  }

 private:
  float resolution_m_;
  float inv_resolution_;
  float clamp_m_;
  float step_m_;  // metres per 8-bit step
  Eigen::Vector3f origin_m_ = Eigen::Vector3f::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();        // cells per axis (multiples of kBlockEdge)
  Eigen::Vector3i block_dims_ = Eigen::Vector3i::Zero();  // blocks per axis
  std::vector<std::int32_t> block_index_;                 // block slot -> block number, -1 when not stored
  std::vector<std::uint8_t> cells_;                       // kBlockCells codes per stored block
  std::vector<std::int32_t> nearest_;                     // per stored cell: nearest point, -1 when none
  std::vector<Eigen::Vector3f> points_;                   // the submap points
  std::vector<Eigen::Vector3f> normals_;                  // their unit normals (zero: not planar)

  static std::size_t LocalIndex(int x, int y, int z) {
    constexpr int kLast = kBlockEdge - 1;
    return static_cast<std::size_t>((((x & kLast) << kBlockShift) + (y & kLast)) * kBlockEdge + (z & kLast));
  }

  std::size_t BlockSlot(int bx, int by, int bz) const {
    return (static_cast<std::size_t>(bx) * static_cast<std::size_t>(block_dims_.y()) + static_cast<std::size_t>(by)) *
               static_cast<std::size_t>(block_dims_.z()) +
           static_cast<std::size_t>(bz);
  }
};

}  // namespace unimap::graph
