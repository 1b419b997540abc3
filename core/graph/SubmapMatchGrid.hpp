#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace unimap::graph {

// Coarse multi-resolution score grids of a submap for the branch-and-bound
// loop-closure search (the precomputation grids of Hess et al. 2016,
// "Real-Time Loop Closure in 2D LIDAR SLAM", sec. V-C, pooled over x and y
// only since z is searched exhaustively). Level 0 holds, per cell, the score
// max(0, 1 - d / kernel_m) of the distance d from the cell's volume to the
// nearest submap point, as 0..255. Level h holds, per cell c, the maximum of
// level 0 over the xy window [c, c + 2^h) x [c, c + 2^h) (same z), so the
// summed level-h values of a scan translated by t bound (from above) its
// level-0 score for every translation of the window t + [0, 2^h) cells in x
// and y. The grid is padded by 2^(levels-1) - 1 empty cells on the low x and
// y sides, so windows starting before the points are exact too. Immutable
// after construction; safe to share between threads.
class SubmapMatchGrid {
 public:
  // Largest number of cells per level; a larger box is an InputError.
  static constexpr std::size_t kMaxCells = std::size_t{1} << 28;

  // Builds the levels from submap points (submap frame, all finite, at least
  // one). resolution_m, kernel_m > 0; levels >= 1. Throws unimap::InputError
  // when the box needs more than kMaxCells cells.
  SubmapMatchGrid(const std::vector<Eigen::Vector3f>& points_submap, double resolution_m, double kernel_m, int levels);

  // Cell containing p (submap frame); may lie outside the grid.
  Eigen::Vector3i CellOf(const Eigen::Vector3d& p_submap) const {
    const Eigen::Vector3d f = (p_submap - origin_m_) * inv_resolution_;
    return Eigen::Vector3i(static_cast<int>(std::floor(f.x())), static_cast<int>(std::floor(f.y())),
                           static_cast<int>(std::floor(f.z())));
  }
  // Level-h value (0..255) of a cell; 0 outside the grid.
  std::uint8_t Value(int level, const Eigen::Vector3i& cell) const;
  // Raw cells of a level: index (x * dims.y + y) * dims.z + z.
  const std::uint8_t* Level(int level) const { return levels_[static_cast<std::size_t>(level)].data(); }

  int levels() const { return static_cast<int>(levels_.size()); }  // number of levels
  double resolution() const { return resolution_m_; }              // cell edge (m)
  const Eigen::Vector3d& origin() const { return origin_m_; }      // min corner of cell (0, 0, 0), submap frame (m)
  const Eigen::Vector3i& dims() const { return dims_; }            // cells per axis (padding included)
  std::size_t MemoryBytes() const;                                 // bytes held by the levels

 private:
  double resolution_m_;
  double inv_resolution_;
  Eigen::Vector3d origin_m_ = Eigen::Vector3d::Zero();
  Eigen::Vector3i dims_ = Eigen::Vector3i::Zero();
  std::vector<std::vector<std::uint8_t>> levels_;

  // Level 0 from the points (the kernel of the point-to-cell-box distance).
  void BuildBase(const std::vector<Eigen::Vector3f>& points_submap, double kernel_m);
  // Level h from level h - 1: max of four cells 2^(h-1) apart in x and y.
  void BuildPooled(int level);
};

}  // namespace unimap::graph
