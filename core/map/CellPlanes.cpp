#include "map/CellPlanes.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace unimap::map {

namespace {

// Height code meaning "no plane".
constexpr std::int16_t kNone = std::numeric_limits<std::int16_t>::min();

float SignNotZero(float v) { return v >= 0.0f ? 1.0f : -1.0f; }

// Octahedral map of a unit vector to [-1, 1]^2 (the lower half folded over
// the diagonals), then 255 levels per coordinate (0 exact, so axis-aligned
// normals are): within a degree.
std::uint16_t EncodeNormal(const Eigen::Vector3f& n) {
  const float l1 = std::abs(n.x()) + std::abs(n.y()) + std::abs(n.z());
  float u = n.x() / l1;
  float v = n.y() / l1;
  if (n.z() < 0.0f) {
    const float fu = (1.0f - std::abs(v)) * SignNotZero(u);
    const float fv = (1.0f - std::abs(u)) * SignNotZero(v);
    u = fu;
    v = fv;
  }
  const auto quantise = [](float c) {
    return static_cast<std::uint16_t>(std::lround((std::clamp(c, -1.0f, 1.0f) + 1.0f) * 127.0f));
  };
  return static_cast<std::uint16_t>(quantise(u) << 8 | quantise(v));
}

Eigen::Vector3f DecodeNormal(std::uint16_t code) {
  const float u = static_cast<float>(code >> 8) / 127.0f - 1.0f;
  const float v = static_cast<float>(code & 0xff) / 127.0f - 1.0f;
  Eigen::Vector3f n(u, v, 1.0f - std::abs(u) - std::abs(v));
  if (n.z() < 0.0f) {
    const float fx = (1.0f - std::abs(v)) * SignNotZero(u);
    const float fy = (1.0f - std::abs(u)) * SignNotZero(v);
    n.x() = fx;
    n.y() = fy;
  }
  return n.normalized();
}

}  // namespace

CellPlanes::CellPlanes(std::size_t cell_count) : cells_(cell_count, static_cast<std::uint16_t>(kNone)) {}

void CellPlanes::Set(std::size_t index, const Eigen::Vector3f& normal, float center_height_m) {
  assert(index < cells_.size());
  const float steps = std::clamp(std::round(center_height_m / kHeightStepM), -32767.0f, 32767.0f);
  const auto height = static_cast<std::uint16_t>(static_cast<std::int16_t>(steps));
  cells_[index] = static_cast<std::uint32_t>(EncodeNormal(normal)) << 16 | height;
}

bool CellPlanes::Get(std::size_t index, Eigen::Vector3f* normal, float* center_height_m) const {
  assert(index < cells_.size());
  const std::uint32_t cell = cells_[index];
  const auto height = static_cast<std::int16_t>(cell & 0xffff);
  if (height == kNone) return false;
  *normal = DecodeNormal(static_cast<std::uint16_t>(cell >> 16));
  *center_height_m = static_cast<float>(height) * kHeightStepM;
  return true;
}

}  // namespace unimap::map
