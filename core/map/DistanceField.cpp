#include "map/DistanceField.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "unimap/Errors.hpp"

namespace unimap::map {

namespace {

void RequireClamp(float clamp_m) {
  if (!(std::isfinite(clamp_m) && clamp_m > 0.0f)) {
    throw InputError("DistanceField: clamp distance must be positive and finite, got " + std::to_string(clamp_m));
  }
}

// True when some edge of the 2 x 2 x 2 stencil c (c[4 dx + 2 dy + dz])
// joins values more than max_jump_m apart. Distances of neighbouring cells
// differ by at most the edge length, and across a surface between them
// (opposite signs) |a - b| = |a| + |b| is at most that too (each end is at
// most its |value| from the surface); a larger jump is where the two sides
// of a surface's edge meet, or the reach of the transform ends, not a
// surface.
bool JumpAlongAnEdge(const float (&c)[8], float max_jump_m) {
  int jump = 0;  // branch-free
  for (int k = 0; k < 4; ++k) {
    jump |= static_cast<int>(std::abs(c[k] - c[k + 4]) > max_jump_m);          // along x
    const int y0 = (k & 1) | ((k & 2) << 1);                                   // 0 1 4 5
    jump |= static_cast<int>(std::abs(c[y0] - c[y0 + 2]) > max_jump_m);        // along y
    jump |= static_cast<int>(std::abs(c[2 * k] - c[2 * k + 1]) > max_jump_m);  // along z
  }
  return jump != 0;
}

}  // namespace

DistanceField::DistanceField(float clamp_m, std::uint64_t sequence)
    : clamp_m_(clamp_m), step_m_(clamp_m / static_cast<float>(kMaxSteps)), sequence_(sequence) {
  RequireClamp(clamp_m);
}

DistanceField::DistanceField(const Eigen::Vector3f& origin_m, const Eigen::Vector3i& dims, float resolution_m,
                             float clamp_m, std::vector<std::uint16_t> cells, std::uint64_t sequence)
    : DistanceField(origin_m, dims, resolution_m, clamp_m, std::move(cells), sequence, Encoding::kUnsigned) {}

DistanceField::DistanceField(const Eigen::Vector3f& origin_m, const Eigen::Vector3i& dims, float resolution_m,
                             float clamp_m, std::vector<std::uint16_t> cells, std::uint64_t sequence, Encoding encoding)
    : origin_m_(origin_m),
      dims_(dims),
      dims_f_(dims.cast<float>()),
      resolution_m_(resolution_m),
      inv_resolution_(1.0f / resolution_m),
      clamp_m_(clamp_m),
      step_m_(encoding == Encoding::kSigned ? 2.0f * clamp_m / static_cast<float>(kMaxSignedSteps)
                                            : clamp_m / static_cast<float>(kMaxSteps)),
      offset_m_(encoding == Encoding::kSigned ? clamp_m : 0.0f),
      shift_(encoding == Encoding::kSigned ? 1 : 0),
      flag_mask_(encoding == Encoding::kSigned ? 1 : 0),
      max_crossing_m_(kMaxCrossingSum * resolution_m),
      stride_x_(static_cast<std::size_t>(dims.y()) * static_cast<std::size_t>(dims.z())),
      stride_y_(static_cast<std::size_t>(dims.z())),
      clamp_code_(encoding == Encoding::kSigned ? static_cast<std::uint16_t>(kMaxSignedSteps << 1) : kMaxSteps),
      sequence_(sequence) {
  RequireClamp(clamp_m);
  if (!(std::isfinite(resolution_m) && resolution_m > 0.0f) || !origin_m.allFinite()) {
    throw InputError("DistanceField: resolution must be positive and the origin finite");
  }
  if ((dims.array() < 0).any()) throw InputError("DistanceField: negative grid size");
  const std::size_t expected = stride_x_ * static_cast<std::size_t>(dims.x());
  if (expected != cells.size()) {
    throw InputError("DistanceField: grid " + std::to_string(dims.x()) + "x" + std::to_string(dims.y()) + "x" +
                     std::to_string(dims.z()) + " needs " + std::to_string(expected) + " cells, got " +
                     std::to_string(cells.size()));
  }
  if (encoding == Encoding::kSigned) FlagJumpingStencils(&cells);
  StoreBlocks(cells);
}

DistanceField::DistanceField(const Eigen::Vector3f& origin_m, const Eigen::Vector3i& block_dims, float resolution_m,
                             float clamp_m, std::vector<std::shared_ptr<const Block>> blocks, std::uint64_t sequence)
    : origin_m_(origin_m),
      dims_(block_dims * kBlockEdge),
      dims_f_((block_dims * kBlockEdge).cast<float>()),
      resolution_m_(resolution_m),
      inv_resolution_(1.0f / resolution_m),
      clamp_m_(clamp_m),
      step_m_(clamp_m / static_cast<float>(kMaxSteps)),
      max_crossing_m_(kMaxCrossingSum * resolution_m),
      stride_x_(static_cast<std::size_t>(dims_.y()) * static_cast<std::size_t>(dims_.z())),
      stride_y_(static_cast<std::size_t>(dims_.z())),
      block_dims_(block_dims),
      block_stride_x_(static_cast<std::size_t>(block_dims.y()) * static_cast<std::size_t>(block_dims.z())),
      block_stride_y_(static_cast<std::size_t>(block_dims.z())),
      blocks_(std::move(blocks)),
      sequence_(sequence) {
  RequireClamp(clamp_m);
  if (!(std::isfinite(resolution_m) && resolution_m > 0.0f) || !origin_m.allFinite()) {
    throw InputError("DistanceField: resolution must be positive and the origin finite");
  }
  if ((block_dims.array() < 0).any()) throw InputError("DistanceField: negative grid size");
  const std::size_t expected = block_stride_x_ * static_cast<std::size_t>(block_dims.x());
  if (expected != blocks_.size()) {
    throw InputError("DistanceField: " + std::to_string(block_dims.x()) + "x" + std::to_string(block_dims.y()) + "x" +
                     std::to_string(block_dims.z()) + " blocks need " + std::to_string(expected) + " entries, got " +
                     std::to_string(blocks_.size()));
  }
  for (const auto& block : blocks_) {
    if (block != nullptr && block->size() != static_cast<std::size_t>(kBlockCells)) {
      throw InputError("DistanceField: a block holds " + std::to_string(block->size()) + " cells, not " +
                       std::to_string(kBlockCells));
    }
  }
}

void DistanceField::StoreBlocks(const std::vector<std::uint16_t>& cells) {
  block_dims_ = (dims_.array() + kBlockMask) / kBlockEdge;
  block_stride_x_ = static_cast<std::size_t>(block_dims_.y()) * static_cast<std::size_t>(block_dims_.z());
  block_stride_y_ = static_cast<std::size_t>(block_dims_.z());
  blocks_.assign(block_stride_x_ * static_cast<std::size_t>(block_dims_.x()), nullptr);
  for (int bx = 0; bx < block_dims_.x(); ++bx) {
    for (int by = 0; by < block_dims_.y(); ++by) {
      for (int bz = 0; bz < block_dims_.z(); ++bz) {
        auto block = std::make_shared<Block>(static_cast<std::size_t>(kBlockCells), clamp_code_);
        bool stored = false;
        for (int x = 0; x < kBlockEdge && bx * kBlockEdge + x < dims_.x(); ++x) {
          for (int y = 0; y < kBlockEdge && by * kBlockEdge + y < dims_.y(); ++y) {
            const std::size_t row = static_cast<std::size_t>(bx * kBlockEdge + x) * stride_x_ +
                                    static_cast<std::size_t>(by * kBlockEdge + y) * stride_y_;
            for (int z = 0; z < kBlockEdge && bz * kBlockEdge + z < dims_.z(); ++z) {
              const std::uint16_t code = cells[row + static_cast<std::size_t>(bz * kBlockEdge + z)];
              (*block)[static_cast<std::size_t>(BlockOffset(x, y, z))] = code;
              stored = stored || code != clamp_code_;
            }
          }
        }
        if (stored) {
          blocks_[static_cast<std::size_t>(bx) * block_stride_x_ + static_cast<std::size_t>(by) * block_stride_y_ +
                  static_cast<std::size_t>(bz)] = std::move(block);
        }
      }
    }
  }
}

void DistanceField::ForEachCellWithin(float max_distance_m,
                                      const std::function<void(const Eigen::Vector3i&)>& visit) const {
  for (int bx = 0; bx < block_dims_.x(); ++bx) {
    for (int by = 0; by < block_dims_.y(); ++by) {
      for (int bz = 0; bz < block_dims_.z(); ++bz) {
        const Block* block = blocks_[static_cast<std::size_t>(bx) * block_stride_x_ +
                                     static_cast<std::size_t>(by) * block_stride_y_ + static_cast<std::size_t>(bz)]
                                 .get();
        if (block == nullptr) continue;
        for (int x = 0; x < kBlockEdge; ++x) {
          for (int y = 0; y < kBlockEdge; ++y) {
            for (int z = 0; z < kBlockEdge; ++z) {
              const Eigen::Vector3i cell(bx * kBlockEdge + x, by * kBlockEdge + y, bz * kBlockEdge + z);
              if ((cell.array() >= dims_.array()).any()) continue;
              const std::uint16_t code = (*block)[static_cast<std::size_t>(BlockOffset(x, y, z))];
              if (std::abs(static_cast<float>(code >> shift_) * step_m_ - offset_m_) <= max_distance_m) visit(cell);
            }
          }
        }
      }
    }
  }
}

std::size_t DistanceField::StoredBlocks() const {
  return static_cast<std::size_t>(
      std::count_if(blocks_.begin(), blocks_.end(), [](const auto& block) { return block != nullptr; }));
}

void DistanceField::FlagJumpingStencils(std::vector<std::uint16_t>* cells_out) const {
  std::vector<std::uint16_t>& cells = *cells_out;
  // Largest step difference along an edge that a surface can explain.
  const int max_steps = static_cast<int>(max_crossing_m_ / step_m_);
  const auto nx = static_cast<std::size_t>(dims_.x());
  const auto ny = static_cast<std::size_t>(dims_.y());
  const auto nz = static_cast<std::size_t>(dims_.z());
  // Per cell, the edges towards +z (bit 0), +y (bit 1) and +x (bit 2) that jump.
  std::vector<std::uint8_t> jumps(cells.size(), 0);
  const auto jump = [&](std::size_t a, std::size_t b) {
    const int difference = static_cast<int>(cells[a] >> 1) - static_cast<int>(cells[b] >> 1);
    return static_cast<std::uint8_t>(std::abs(difference) > max_steps);
  };
  for (std::size_t x = 0; x < nx; ++x) {
    for (std::size_t y = 0; y < ny; ++y) {
      const std::size_t row = x * stride_x_ + y * stride_y_;
      for (std::size_t z = 0; z + 1 < nz; ++z) jumps[row + z] |= jump(row + z, row + z + 1);
      if (y + 1 < ny) {
        for (std::size_t z = 0; z < nz; ++z) {
          jumps[row + z] |= static_cast<std::uint8_t>(jump(row + z, row + z + stride_y_) << 1);
        }
      }
      if (x + 1 < nx) {
        for (std::size_t z = 0; z < nz; ++z) {
          jumps[row + z] |= static_cast<std::uint8_t>(jump(row + z, row + z + stride_x_) << 2);
        }
      }
    }
  }
  // A stencil's 12 edges: 4 along each axis, from the cells of its face
  // across that axis.
  const std::size_t sx = stride_x_;
  const std::size_t sy = stride_y_;
  for (std::size_t x = 0; x + 1 < nx; ++x) {
    for (std::size_t y = 0; y + 1 < ny; ++y) {
      const std::size_t row = x * sx + y * sy;
      for (std::size_t z = 0; z + 1 < nz; ++z) {
        const std::size_t i = row + z;
        const int along_z = (jumps[i] | jumps[i + sy] | jumps[i + sx] | jumps[i + sx + sy]) & 1;
        const int along_y = (jumps[i] | jumps[i + 1] | jumps[i + sx] | jumps[i + sx + 1]) & 2;
        const int along_x = (jumps[i] | jumps[i + 1] | jumps[i + sy] | jumps[i + sy + 1]) & 4;
        cells[i] = static_cast<std::uint16_t>(cells[i] | ((along_z | along_y | along_x) != 0));
      }
    }
  }
}

void DistanceField::SetPlanes(CellPlanes planes) {
  if (planes.size() != CellCount()) {
    throw InputError("DistanceField: " + std::to_string(planes.size()) + " cell planes for " +
                     std::to_string(CellCount()) + " cells");
  }
  planes_ = std::move(planes);
}

bool DistanceField::PlaneAt(const Eigen::Vector3f& p_map, Eigen::Vector3f* normal, float* offset_m) const {
  if (planes_.size() == 0) return false;
  const Eigen::Vector3f f = (p_map - origin_m_) * inv_resolution_;
  if (!((f.array() >= 0.0f).all() && (f.array() < dims_f_.array()).all())) return false;
  const Eigen::Vector3i cell = f.cast<int>();
  float center_height_m = 0.0f;
  if (!planes_.Get(CellIndex(cell), normal, &center_height_m)) return false;
  // height(x) = h_c + n . (x - c) = n . x + (h_c - n . c).
  *offset_m = center_height_m - normal->dot(CellCenter(cell));
  return true;
}

float DistanceField::CellDistance(const Eigen::Vector3i& cell) const { return std::abs(CellValue(cell)); }

float DistanceField::CellValue(const Eigen::Vector3i& cell) const {
  if ((cell.array() < 0).any() || (cell.array() >= dims_.array()).any()) return clamp_m_;
  return static_cast<float>(Code(cell.x(), cell.y(), cell.z()) >> shift_) * step_m_ - offset_m_;
}

Eigen::Vector3f DistanceField::CellCenter(const Eigen::Vector3i& cell) const {
  return origin_m_ + (cell.cast<float>().array() + 0.5f).matrix() * resolution_m_;
}

bool DistanceField::Contains(const Eigen::Vector3f& p_map) const {
  const Eigen::Vector3f f = (p_map - origin_m_) * inv_resolution_;
  return (f.array() >= 0.0f).all() && (f.array() < dims_f_.array()).all();
}

Eigen::Vector3f DistanceField::box_max() const { return origin_m_ + dims_f_ * resolution_m_; }

bool DistanceField::InBoxStencil(int ix, int iy, int iz, float* c) const {
  bool jump = false;  // signed stencil whose sign changes cannot all be surfaces
  if ((ix & kBlockMask) != kBlockMask && (iy & kBlockMask) != kBlockMask && (iz & kBlockMask) != kBlockMask) {
    // One block: direct loads (a missing block reads the clamp everywhere).
    const Block* block = BlockAt(ix, iy, iz);
    if (block == nullptr) return false;
    const std::uint16_t* first = block->data() + BlockOffset(ix & kBlockMask, iy & kBlockMask, iz & kBlockMask);
    constexpr int kStrideX = kBlockEdge * kBlockEdge;
    constexpr int kStrideY = kBlockEdge;
    // Each code converted as it is loaded (no array of codes: its narrow
    // stores and wide reload stalled the lookup).
    for (int k = 0; k < 8; ++k) {
      c[k] = static_cast<float>(first[(k >> 2) * kStrideX + ((k >> 1) & 1) * kStrideY + (k & 1)] >> shift_) * step_m_ -
             offset_m_;
    }
    jump = (first[0] & flag_mask_) != 0;  // flagged by FlagJumpingStencils
  } else {
    for (int k = 0; k < 8; ++k) {
      c[k] = static_cast<float>(Code(ix + (k >> 2), iy + ((k >> 1) & 1), iz + (k & 1)) >> shift_) * step_m_ - offset_m_;
    }
    jump = (Code(ix, iy, iz) & flag_mask_) != 0;
  }
  // Signed fields interpolate the signed values only where their sign
  // changes can be surfaces (kMaxCrossingSum); otherwise the magnitudes
  // (the same for stencils of one sign).
  if (jump) {
    for (int k = 0; k < 8; ++k) c[k] = std::abs(c[k]);
  }
  return true;
}

void DistanceField::DistancesTrilinear(const Eigen::Vector3f* points_map, int n, float* out) const {
  // The particles of one scan point fall in a few neighbouring stencils:
  // each stencil's eight values are loaded once into a direct-mapped cache
  // indexed by the low two bits of its cell per axis (a 4^3 neighbourhood
  // never collides), so a point's particles reuse them in any order. The
  // arithmetic is DistanceTrilinear's: the same values.
  struct Stencil {
    int x = -1, y = -1, z = -1;  // first cell; -1: empty (cells are >= 0)
    bool stored = false;         // InBoxStencil's result
    float c[8];
  };
  Stencil cache[64];
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3f& p_map = points_map[i];
    const float ux = (p_map.x() - origin_m_.x()) * inv_resolution_ - 0.5f;
    const float uy = (p_map.y() - origin_m_.y()) * inv_resolution_ - 0.5f;
    const float uz = (p_map.z() - origin_m_.z()) * inv_resolution_ - 0.5f;
    if (!(ux >= 0.0f && uy >= 0.0f && uz >= 0.0f && ux < dims_f_.x() - 1.0f && uy < dims_f_.y() - 1.0f &&
          uz < dims_f_.z() - 1.0f)) {
      out[i] = DistanceTrilinear(p_map, nullptr);
      continue;
    }
    const int ix = static_cast<int>(ux);
    const int iy = static_cast<int>(uy);
    const int iz = static_cast<int>(uz);
    Stencil& stencil = cache[((ix & 3) << 4) | ((iy & 3) << 2) | (iz & 3)];
    if (ix != stencil.x || iy != stencil.y || iz != stencil.z) {
      stencil.stored = InBoxStencil(ix, iy, iz, stencil.c);
      stencil.x = ix;
      stencil.y = iy;
      stencil.z = iz;
    }
    const float* c = stencil.c;
    if (!stencil.stored) {
      out[i] = clamp_m_;
      continue;
    }
    const float tx = ux - static_cast<float>(ix);
    const float ty = uy - static_cast<float>(iy);
    const float tz = uz - static_cast<float>(iz);
    float cz[2][2];
    for (int dx = 0; dx < 2; ++dx) {
      for (int dy = 0; dy < 2; ++dy) {
        const float c0 = c[4 * dx + 2 * dy];
        const float c1 = c[4 * dx + 2 * dy + 1];
        cz[dx][dy] = c0 + tz * (c1 - c0);
      }
    }
    const float cy0 = cz[0][0] + ty * (cz[0][1] - cz[0][0]);
    const float cy1 = cz[1][0] + ty * (cz[1][1] - cz[1][0]);
    out[i] = std::abs(cy0 + tx * (cy1 - cy0));
  }
}

float DistanceField::DistanceTrilinear(const Eigen::Vector3f& p_map, Eigen::Vector3f* gradient_map) const {
  // Sample coordinates with voxel centres at integers.
  const float ux = (p_map.x() - origin_m_.x()) * inv_resolution_ - 0.5f;
  const float uy = (p_map.y() - origin_m_.y()) * inv_resolution_ - 0.5f;
  const float uz = (p_map.z() - origin_m_.z()) * inv_resolution_ - 0.5f;
  float c[8];  // corner values, c[4 dx + 2 dy + dz] at i0 + (dx, dy, dz)
  float t[3];  // position within the stencil
  if (ux >= 0.0f && uy >= 0.0f && uz >= 0.0f && ux < dims_f_.x() - 1.0f && uy < dims_f_.y() - 1.0f &&
      uz < dims_f_.z() - 1.0f) {
    // All eight centres inside (and u finite): truncation is the floor.
    const int ix = static_cast<int>(ux);
    const int iy = static_cast<int>(uy);
    const int iz = static_cast<int>(uz);
    t[0] = ux - static_cast<float>(ix);
    t[1] = uy - static_cast<float>(iy);
    t[2] = uz - static_cast<float>(iz);
    if (!InBoxStencil(ix, iy, iz, c)) {
      if (gradient_map != nullptr) gradient_map->setZero();
      return clamp_m_;
    }
  } else {
    const Eigen::Vector3f u(ux, uy, uz);
    if (!u.allFinite() || (u.array() < -1.0f).any() || (u.array() >= dims_f_.array()).any()) {
      if (gradient_map != nullptr) gradient_map->setZero();
      return clamp_m_;
    }
    const Eigen::Vector3f base = u.array().floor();
    const Eigen::Vector3i i0 = base.cast<int>();
    for (int a = 0; a < 3; ++a) t[a] = u[a] - base[a];
    for (int k = 0; k < 8; ++k) c[k] = CellValue(i0 + Eigen::Vector3i(k >> 2, (k >> 1) & 1, k & 1));
    // Signed fields interpolate the signed values only where their sign
    // changes can be surfaces (kMaxCrossingSum); otherwise the magnitudes
    // (the same for stencils of one sign).
    if (offset_m_ > 0.0f && JumpAlongAnEdge(c, max_crossing_m_)) {
      for (float& value : c) value = std::abs(value);
    }
  }
  // Interpolate along z, then y, then x; derivatives by the product rule.
  float cz[2][2];
  float dcz[2][2];
  for (int dx = 0; dx < 2; ++dx) {
    for (int dy = 0; dy < 2; ++dy) {
      const float c0 = c[4 * dx + 2 * dy];
      const float c1 = c[4 * dx + 2 * dy + 1];
      cz[dx][dy] = c0 + t[2] * (c1 - c0);
      dcz[dx][dy] = c1 - c0;
    }
  }
  const float cy0 = cz[0][0] + t[1] * (cz[0][1] - cz[0][0]);
  const float cy1 = cz[1][0] + t[1] * (cz[1][1] - cz[1][0]);
  const float value = cy0 + t[0] * (cy1 - cy0);
  // |s|: a negative interpolated value (behind a surface) flips with its gradient.
  const float sign = std::copysign(1.0f, value);
  if (gradient_map != nullptr) {
    const float dy0 = cz[0][1] - cz[0][0];
    const float dy1 = cz[1][1] - cz[1][0];
    const float dz0 = dcz[0][0] + t[1] * (dcz[0][1] - dcz[0][0]);
    const float dz1 = dcz[1][0] + t[1] * (dcz[1][1] - dcz[1][0]);
    *gradient_map =
        Eigen::Vector3f(cy1 - cy0, dy0 + t[0] * (dy1 - dy0), dz0 + t[0] * (dz1 - dz0)) * (sign * inv_resolution_);
  }
  return std::abs(value);
}

}  // namespace unimap::map
