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
    throw InputError("DistanceField: clamp distance must be positive and finite, got " +
                     std::to_string(clamp_m));
  }
}

}  // namespace

DistanceField::DistanceField(float clamp_m, std::uint64_t sequence)
    : clamp_m_(clamp_m), step_m_(clamp_m / static_cast<float>(kMaxSteps)), sequence_(sequence) {
  RequireClamp(clamp_m);
}

DistanceField::DistanceField(const Eigen::Vector3f& origin_m, const Eigen::Vector3i& dims,
                             float resolution_m, float clamp_m, std::vector<std::uint16_t> cells,
                             std::uint64_t sequence)
    : origin_m_(origin_m),
      dims_(dims),
      dims_f_(dims.cast<float>()),
      resolution_m_(resolution_m),
      inv_resolution_(1.0f / resolution_m),
      clamp_m_(clamp_m),
      step_m_(clamp_m / static_cast<float>(kMaxSteps)),
      stride_x_(static_cast<std::size_t>(dims.y()) * static_cast<std::size_t>(dims.z())),
      stride_y_(static_cast<std::size_t>(dims.z())),
      cells_(std::move(cells)),
      sequence_(sequence) {
  RequireClamp(clamp_m);
  if (!(std::isfinite(resolution_m) && resolution_m > 0.0f) || !origin_m.allFinite()) {
    throw InputError("DistanceField: resolution must be positive and the origin finite");
  }
  if ((dims.array() < 0).any()) throw InputError("DistanceField: negative grid size");
  const std::size_t expected = stride_x_ * static_cast<std::size_t>(dims.x());
  if (expected != cells_.size()) {
    throw InputError("DistanceField: grid " + std::to_string(dims.x()) + "x" +
                     std::to_string(dims.y()) + "x" + std::to_string(dims.z()) + " needs " +
                     std::to_string(expected) + " cells, got " + std::to_string(cells_.size()));
  }
}

std::uint16_t DistanceField::Quantise(float distance_m, float clamp_m) {
  if (!(distance_m < clamp_m)) return kMaxSteps;  // also NaN
  if (distance_m <= 0.0f) return 0;
  const float steps = std::round(distance_m / clamp_m * static_cast<float>(kMaxSteps));
  return static_cast<std::uint16_t>(std::min(steps, static_cast<float>(kMaxSteps)));
}

float DistanceField::CellDistance(const Eigen::Vector3i& cell) const {
  if ((cell.array() < 0).any() || (cell.array() >= dims_.array()).any()) return clamp_m_;
  const std::size_t index = static_cast<std::size_t>(cell.x()) * stride_x_ +
                            static_cast<std::size_t>(cell.y()) * stride_y_ +
                            static_cast<std::size_t>(cell.z());
  return static_cast<float>(cells_[index]) * step_m_;
}

Eigen::Vector3f DistanceField::CellCentre(const Eigen::Vector3i& cell) const {
  return origin_m_ + (cell.cast<float>().array() + 0.5f).matrix() * resolution_m_;
}

bool DistanceField::Contains(const Eigen::Vector3f& p_map) const {
  const Eigen::Vector3f f = (p_map - origin_m_) * inv_resolution_;
  return (f.array() >= 0.0f).all() && (f.array() < dims_f_.array()).all();
}

Eigen::Vector3f DistanceField::box_max() const { return origin_m_ + dims_f_ * resolution_m_; }

float DistanceField::DistanceTrilinear(const Eigen::Vector3f& p_map,
                                       Eigen::Vector3f* gradient_map) const {
  // Sample coordinates with voxel centres at integers.
  const Eigen::Vector3f u = (p_map - origin_m_) * inv_resolution_ - Eigen::Vector3f::Constant(0.5f);
  if (!u.allFinite() || (u.array() < -1.0f).any() || (u.array() >= dims_f_.array()).any()) {
    if (gradient_map != nullptr) gradient_map->setZero();
    return clamp_m_;
  }
  const Eigen::Vector3f base = u.array().floor();
  const Eigen::Vector3i i0 = base.cast<int>();
  const Eigen::Vector3f t = u - base;
  float c[2][2][2];
  if ((i0.array() >= 0).all() && (i0.array() + 1 < dims_.array()).all()) {
    // All eight centres inside: direct loads.
    const std::uint16_t* base_cell = cells_.data() + static_cast<std::size_t>(i0.x()) * stride_x_ +
                                     static_cast<std::size_t>(i0.y()) * stride_y_ +
                                     static_cast<std::size_t>(i0.z());
    for (int dx = 0; dx < 2; ++dx) {
      for (int dy = 0; dy < 2; ++dy) {
        const std::uint16_t* row = base_cell + static_cast<std::size_t>(dx) * stride_x_ +
                                   static_cast<std::size_t>(dy) * stride_y_;
        c[dx][dy][0] = static_cast<float>(row[0]) * step_m_;
        c[dx][dy][1] = static_cast<float>(row[1]) * step_m_;
      }
    }
  } else {
    for (int dx = 0; dx < 2; ++dx) {
      for (int dy = 0; dy < 2; ++dy) {
        for (int dz = 0; dz < 2; ++dz) c[dx][dy][dz] = CellDistance(i0 + Eigen::Vector3i(dx, dy, dz));
      }
    }
  }
  // Interpolate along z, then y, then x; derivatives by the product rule.
  float cz[2][2];
  float dcz[2][2];
  for (int dx = 0; dx < 2; ++dx) {
    for (int dy = 0; dy < 2; ++dy) {
      cz[dx][dy] = c[dx][dy][0] + t.z() * (c[dx][dy][1] - c[dx][dy][0]);
      dcz[dx][dy] = c[dx][dy][1] - c[dx][dy][0];
    }
  }
  const float cy0 = cz[0][0] + t.y() * (cz[0][1] - cz[0][0]);
  const float cy1 = cz[1][0] + t.y() * (cz[1][1] - cz[1][0]);
  const float value = cy0 + t.x() * (cy1 - cy0);
  if (gradient_map != nullptr) {
    const float dy0 = cz[0][1] - cz[0][0];
    const float dy1 = cz[1][1] - cz[1][0];
    const float dz0 = dcz[0][0] + t.y() * (dcz[0][1] - dcz[0][0]);
    const float dz1 = dcz[1][0] + t.y() * (dcz[1][1] - dcz[1][0]);
    *gradient_map = Eigen::Vector3f(cy1 - cy0, dy0 + t.x() * (dy1 - dy0), dz0 + t.x() * (dz1 - dz0)) *
                    inv_resolution_;
  }
  return value;
}

}  // namespace unimap::map
