#include "graph/LoopClosureDistanceField.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

#include "graph/LoopClosureNormals.hpp"
#include "unimap/Errors.hpp"

namespace unimap::graph {

namespace {

// Cells whose centres lie within clamp_m of p along every axis, clipped to
// the grid: [lo, hi] per axis (empty when lo > hi).
void CellRange(const Eigen::Vector3f& p, const Eigen::Vector3f& origin_m, float inv_resolution, float clamp_m,
               const Eigen::Vector3i& dims, Eigen::Vector3i* lo, Eigen::Vector3i* hi) {
  for (int a = 0; a < 3; ++a) {
    (*lo)[a] = std::max(0, static_cast<int>(std::ceil((p[a] - clamp_m - origin_m[a]) * inv_resolution - 0.5f)));
    (*hi)[a] =
        std::min(dims[a] - 1, static_cast<int>(std::floor((p[a] + clamp_m - origin_m[a]) * inv_resolution - 0.5f)));
  }
}

}  // namespace

LoopClosureDistanceField::LoopClosureDistanceField(const std::vector<Eigen::Vector3f>& points_submap,
                                                   double resolution_m, double clamp_m, double normal_cell_m,
                                                   double planarity_ratio)
    : resolution_m_(static_cast<float>(resolution_m)),
      inv_resolution_(static_cast<float>(1.0 / resolution_m)),
      clamp_m_(static_cast<float>(clamp_m)),
      step_m_(static_cast<float>(clamp_m / 255.0)) {
  assert(resolution_m > 0.0 && clamp_m >= resolution_m && !points_submap.empty());
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(std::numeric_limits<float>::max());
  Eigen::Vector3f hi = -lo;
  for (const Eigen::Vector3f& p : points_submap) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const float margin_m = clamp_m_ + resolution_m_;
  origin_m_ = lo - Eigen::Vector3f::Constant(margin_m);
  double blocks = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double cells = std::ceil(static_cast<double>(hi[a] + margin_m - origin_m_[a]) / resolution_m) + 1.0;
    const double per_axis = std::ceil(cells / kBlockEdge);
    blocks *= per_axis;
    if (blocks > static_cast<double>(kMaxIndexBlocks)) {
      throw InputError("LoopClosureDistanceField: the submap's box needs more than " + std::to_string(kMaxIndexBlocks) +
                       " blocks at " + std::to_string(resolution_m) + " m");
    }
    block_dims_[a] = static_cast<int>(per_axis);
    dims_[a] = block_dims_[a] * kBlockEdge;
  }
  block_index_.assign(static_cast<std::size_t>(blocks), -1);

  // Pass 1: store every block within clamp_m of a point.
  std::int32_t stored = 0;
  Eigen::Vector3i cell_lo;
  Eigen::Vector3i cell_hi;
  for (const Eigen::Vector3f& p : points_submap) {
    CellRange(p, origin_m_, inv_resolution_, clamp_m_, dims_, &cell_lo, &cell_hi);
    if ((cell_lo.array() > cell_hi.array()).any()) continue;
    for (int bx = cell_lo.x() >> kBlockShift; bx <= cell_hi.x() >> kBlockShift; ++bx) {
      for (int by = cell_lo.y() >> kBlockShift; by <= cell_hi.y() >> kBlockShift; ++by) {
        for (int bz = cell_lo.z() >> kBlockShift; bz <= cell_hi.z() >> kBlockShift; ++bz) {
          std::int32_t& slot = block_index_[BlockSlot(bx, by, bz)];
          if (slot < 0) slot = stored++;
        }
      }
    }
  }

  // Pass 2: squared distance to the nearest point, by splatting each point
  // over the cells within clamp_m (per block, rows along z contiguous).
  const float clamp2 = clamp_m_ * clamp_m_;
  std::vector<float> distance2(static_cast<std::size_t>(stored) * kBlockCells, clamp2);
  nearest_.assign(distance2.size(), -1);
  std::vector<float> axis2[3];
  for (std::size_t i = 0; i < points_submap.size(); ++i) {
    const Eigen::Vector3f& p = points_submap[i];
    const auto index = static_cast<std::int32_t>(i);
    CellRange(p, origin_m_, inv_resolution_, clamp_m_, dims_, &cell_lo, &cell_hi);
    if ((cell_lo.array() > cell_hi.array()).any()) continue;
    for (int a = 0; a < 3; ++a) {
      axis2[a].resize(static_cast<std::size_t>(cell_hi[a] - cell_lo[a] + 1));
      for (int c = cell_lo[a]; c <= cell_hi[a]; ++c) {
        const float gap = origin_m_[a] + (static_cast<float>(c) + 0.5f) * resolution_m_ - p[a];
        axis2[a][static_cast<std::size_t>(c - cell_lo[a])] = gap * gap;
      }
    }
    for (int bx = cell_lo.x() >> kBlockShift; bx <= cell_hi.x() >> kBlockShift; ++bx) {
      const int x0 = std::max(cell_lo.x(), bx << kBlockShift);
      const int x1 = std::min(cell_hi.x(), (bx << kBlockShift) + kBlockEdge - 1);
      for (int by = cell_lo.y() >> kBlockShift; by <= cell_hi.y() >> kBlockShift; ++by) {
        const int y0 = std::max(cell_lo.y(), by << kBlockShift);
        const int y1 = std::min(cell_hi.y(), (by << kBlockShift) + kBlockEdge - 1);
        for (int bz = cell_lo.z() >> kBlockShift; bz <= cell_hi.z() >> kBlockShift; ++bz) {
          const int z0 = std::max(cell_lo.z(), bz << kBlockShift);
          const int z1 = std::min(cell_hi.z(), (bz << kBlockShift) + kBlockEdge - 1);
          const std::size_t first = static_cast<std::size_t>(block_index_[BlockSlot(bx, by, bz)]) * kBlockCells;
          float* block = &distance2[first];
          std::int32_t* owner = &nearest_[first];
          const float* dz2 = &axis2[2][static_cast<std::size_t>(z0 - cell_lo.z())];
          const int nz = z1 - z0 + 1;
          for (int x = x0; x <= x1; ++x) {
            const float dx2 = axis2[0][static_cast<std::size_t>(x - cell_lo.x())];
            for (int y = y0; y <= y1; ++y) {
              const float dxy2 = dx2 + axis2[1][static_cast<std::size_t>(y - cell_lo.y())];
              const std::size_t local = LocalIndex(x, y, z0);
              float* row = block + local;
              std::int32_t* row_owner = owner + local;
              for (int k = 0; k < nz; ++k) {
                const float d2 = dxy2 + dz2[k];
                if (d2 < row[k]) {
                  row[k] = d2;
                  row_owner[k] = index;
                }
              }
            }
          }
        }
      }
    }
  }

  points_ = points_submap;
  normals_ = LoopClosureNormals(points_submap, normal_cell_m, planarity_ratio);

  // Pass 3: quantise.
  cells_.resize(distance2.size());
  const float to_steps = 255.0f / clamp_m_;
  for (std::size_t i = 0; i < distance2.size(); ++i) {
    cells_[i] = static_cast<std::uint8_t>(std::min(255.0f, std::sqrt(distance2[i]) * to_steps + 0.5f));
  }
}

float LoopClosureDistanceField::Distance(const Eigen::Vector3f& p_submap, Eigen::Vector3f* gradient_submap) const {
  const Eigen::Vector3f f = (p_submap - origin_m_) * inv_resolution_ - Eigen::Vector3f::Constant(0.5f);
  if (!(f.x() > -1.0f && f.y() > -1.0f && f.z() > -1.0f && f.x() < static_cast<float>(dims_.x()) &&
        f.y() < static_cast<float>(dims_.y()) && f.z() < static_cast<float>(dims_.z()))) {
    if (gradient_submap != nullptr) gradient_submap->setZero();
    return clamp_m_;  // no stored cell around (or NaN)
  }
  const int x = static_cast<int>(std::floor(f.x()));
  const int y = static_cast<int>(std::floor(f.y()));
  const int z = static_cast<int>(std::floor(f.z()));
  const float tx = f.x() - static_cast<float>(x);
  const float ty = f.y() - static_cast<float>(y);
  const float tz = f.z() - static_cast<float>(z);
  float c[8];  // c[4 dx + 2 dy + dz]
  constexpr int kLast = kBlockEdge - 1;
  if (x >= 0 && y >= 0 && z >= 0 && (x & kLast) != kLast && (y & kLast) != kLast && (z & kLast) != kLast) {
    // The whole stencil lies in one block (the common case).
    const std::int32_t block = block_index_[BlockSlot(x >> kBlockShift, y >> kBlockShift, z >> kBlockShift)];
    if (block < 0) {
      if (gradient_submap != nullptr) gradient_submap->setZero();
      return clamp_m_;
    }
    const std::uint8_t* base =
        &cells_[static_cast<std::size_t>(block) * kBlockCells +
                static_cast<std::size_t>((((x & kLast) << kBlockShift) + (y & kLast)) * kBlockEdge + (z & kLast))];
    for (int k = 0; k < 8; ++k) {
      c[k] = static_cast<float>(base[((k >> 2) * kBlockEdge + ((k >> 1) & 1)) * kBlockEdge + (k & 1)]) * step_m_;
    }
  } else {
    for (int k = 0; k < 8; ++k) c[k] = CellDistance(x + (k >> 2), y + ((k >> 1) & 1), z + (k & 1));
  }
  const float c00 = c[0] + tz * (c[1] - c[0]);
  const float c01 = c[2] + tz * (c[3] - c[2]);
  const float c10 = c[4] + tz * (c[5] - c[4]);
  const float c11 = c[6] + tz * (c[7] - c[6]);
  const float c0 = c00 + ty * (c01 - c00);
  const float c1 = c10 + ty * (c11 - c10);
  if (gradient_submap != nullptr) {
    const float dz0 = (1.0f - ty) * (c[1] - c[0]) + ty * (c[3] - c[2]);
    const float dz1 = (1.0f - ty) * (c[5] - c[4]) + ty * (c[7] - c[6]);
    *gradient_submap =
        Eigen::Vector3f((c1 - c0), (1.0f - tx) * (c01 - c00) + tx * (c11 - c10), (1.0f - tx) * dz0 + tx * dz1) *
        inv_resolution_;
  }
  return c0 + tx * (c1 - c0);
}

}  // namespace unimap::graph
