#include "graph/SubmapMatchGrid.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <string>

#include "unimap/Errors.hpp"

namespace unimap::graph {

namespace {

std::size_t Index(const Eigen::Vector3i& dims, int x, int y, int z) {
  return (static_cast<std::size_t>(x) * static_cast<std::size_t>(dims.y()) + static_cast<std::size_t>(y)) *
             static_cast<std::size_t>(dims.z()) +
         static_cast<std::size_t>(z);
}

}  // namespace

SubmapMatchGrid::SubmapMatchGrid(const std::vector<Eigen::Vector3f>& points_submap, double resolution_m,
                                 double kernel_m, int levels)
    : resolution_m_(resolution_m), inv_resolution_(1.0 / resolution_m) {
  assert(resolution_m > 0.0 && kernel_m > 0.0 && levels >= 1 && !points_submap.empty());
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector3d hi = -lo;
  for (const Eigen::Vector3f& p : points_submap) {
    lo = lo.cwiseMin(p.cast<double>());
    hi = hi.cwiseMax(p.cast<double>());
  }
  const double margin_m = kernel_m + resolution_m;
  const int padding = (1 << (levels - 1)) - 1;  // empty low-side cells in x and y
  origin_m_ = lo - Eigen::Vector3d::Constant(margin_m);
  origin_m_.x() -= padding * resolution_m;
  origin_m_.y() -= padding * resolution_m;
  const Eigen::Vector3d extent_cells = (hi + Eigen::Vector3d::Constant(margin_m) - origin_m_) * inv_resolution_;
  double cells = 1.0;
  for (int a = 0; a < 3; ++a) {
    const double n = std::ceil(extent_cells[a]) + 1.0;
    cells *= n;
    if (cells > static_cast<double>(kMaxCells)) {
      throw InputError("SubmapMatchGrid: the submap's box needs more than " + std::to_string(kMaxCells) + " cells at " +
                       std::to_string(resolution_m) + " m");
    }
    dims_[a] = static_cast<int>(n);
  }
  levels_.resize(static_cast<std::size_t>(levels));
  BuildBase(points_submap, kernel_m);
  for (int h = 1; h < levels; ++h) BuildPooled(h);
}

std::uint8_t SubmapMatchGrid::Value(int level, const Eigen::Vector3i& cell) const {
  if ((cell.array() < 0).any() || (cell.array() >= dims_.array()).any()) return 0;
  return Level(level)[Index(dims_, cell.x(), cell.y(), cell.z())];
}

std::size_t SubmapMatchGrid::MemoryBytes() const {
  std::size_t bytes = 0;
  for (const auto& level : levels_) bytes += level.size();
  return bytes;
}

void SubmapMatchGrid::BuildBase(const std::vector<Eigen::Vector3f>& points_submap, double kernel_m) {
  std::vector<std::uint8_t>& base = levels_[0];
  base.assign(
      static_cast<std::size_t>(dims_.x()) * static_cast<std::size_t>(dims_.y()) * static_cast<std::size_t>(dims_.z()),
      0);
  const double half = 0.5 * resolution_m_;
  const double inv_kernel = 1.0 / kernel_m;
  // Per axis: the cells whose box lies within kernel_m of the point, with
  // the squared point-to-box distance along that axis.
  constexpr int kMaxSpan = 64;
  int first[3];
  int count[3];
  double box2[3][kMaxSpan];
  for (const Eigen::Vector3f& pf : points_submap) {
    const Eigen::Vector3d p = pf.cast<double>();
    for (int a = 0; a < 3; ++a) {
      const int lo = std::max(0, static_cast<int>(std::floor((p[a] - kernel_m - origin_m_[a]) * inv_resolution_)));
      const int hi =
          std::min(dims_[a] - 1, static_cast<int>(std::floor((p[a] + kernel_m - origin_m_[a]) * inv_resolution_)));
      first[a] = lo;
      count[a] = std::min(kMaxSpan, hi - lo + 1);
      for (int i = 0; i < count[a]; ++i) {
        const double center = origin_m_[a] + (lo + i + 0.5) * resolution_m_;
        const double gap = std::max(0.0, std::abs(p[a] - center) - half);
        box2[a][i] = gap * gap;
      }
    }
    for (int ix = 0; ix < count[0]; ++ix) {
      for (int iy = 0; iy < count[1]; ++iy) {
        const double xy2 = box2[0][ix] + box2[1][iy];
        std::uint8_t* row = &base[Index(dims_, first[0] + ix, first[1] + iy, first[2])];
        for (int iz = 0; iz < count[2]; ++iz) {
          const double score = 1.0 - std::sqrt(xy2 + box2[2][iz]) * inv_kernel;
          if (score <= 0.0) continue;
          const auto value = static_cast<std::uint8_t>(score * 255.0 + 0.5);
          row[iz] = std::max(row[iz], value);
        }
      }
    }
  }
}

void SubmapMatchGrid::BuildPooled(int level) {
  const std::vector<std::uint8_t>& below = levels_[static_cast<std::size_t>(level - 1)];
  std::vector<std::uint8_t>& out = levels_[static_cast<std::size_t>(level)];
  out.assign(below.size(), 0);
  const int step = 1 << (level - 1);
  const int nz = dims_.z();
  for (int x = 0; x < dims_.x(); ++x) {
    const bool has_x = x + step < dims_.x();
    for (int y = 0; y < dims_.y(); ++y) {
      const bool has_y = y + step < dims_.y();
      std::uint8_t* dst = &out[Index(dims_, x, y, 0)];
      const std::uint8_t* a = &below[Index(dims_, x, y, 0)];
      for (int z = 0; z < nz; ++z) dst[z] = a[z];
      if (has_x) {
        const std::uint8_t* b = &below[Index(dims_, x + step, y, 0)];
        for (int z = 0; z < nz; ++z) dst[z] = std::max(dst[z], b[z]);
      }
      if (has_y) {
        const std::uint8_t* c = &below[Index(dims_, x, y + step, 0)];
        for (int z = 0; z < nz; ++z) dst[z] = std::max(dst[z], c[z]);
      }
      if (has_x && has_y) {
        const std::uint8_t* d = &below[Index(dims_, x + step, y + step, 0)];
        for (int z = 0; z < nz; ++z) dst[z] = std::max(dst[z], d[z]);
      }
    }
  }
}

}  // namespace unimap::graph
