#include "map/CompactPoints.hpp"

#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unimap::map {
namespace {

// deflate's level: the default's ratio at a few milliseconds per retired submap.
constexpr int kLevel = 6;

}  // namespace

CompactPoints::CompactPoints(const std::vector<Eigen::Vector3f>& points) : size_(points.size()) {
  if (points.empty()) return;
  float extent = 0.0f;
  for (const Eigen::Vector3f& p : points) {
    if (p.allFinite()) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  }
  step_ = std::max(kMinStep, extent / 32767.0f);
  // Plane k of axis a holds byte k of each point's difference along a.
  const std::size_t n = points.size();
  std::vector<unsigned char> planes(6 * n);
  for (int a = 0; a < 3; ++a) {
    std::uint16_t previous = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const float v = std::isfinite(points[i](a)) ? std::round(points[i](a) / step_) : 0.0f;
      const auto q = static_cast<std::uint16_t>(static_cast<std::int16_t>(std::clamp(v, -32767.0f, 32767.0f)));
      const auto difference = static_cast<std::uint16_t>(q - previous);
      previous = q;
      planes[(2 * static_cast<std::size_t>(a)) * n + i] = static_cast<unsigned char>(difference & 0xFFu);
      planes[(2 * static_cast<std::size_t>(a) + 1) * n + i] = static_cast<unsigned char>(difference >> 8);
    }
  }
  uLongf packed_size = compressBound(static_cast<uLong>(planes.size()));
  std::vector<unsigned char> packed(packed_size);
  if (compress2(packed.data(), &packed_size, planes.data(), static_cast<uLong>(planes.size()), kLevel) != Z_OK) {
    throw std::bad_alloc();  // zlib fails only for want of memory here
  }
  packed_.assign(packed.begin(), packed.begin() + static_cast<std::ptrdiff_t>(packed_size));
}

std::vector<Eigen::Vector3f> CompactPoints::Expand() const {
  std::vector<Eigen::Vector3f> points;
  if (size_ == 0) return points;
  const std::size_t n = size_;
  std::vector<unsigned char> planes(6 * n);
  uLongf planes_size = static_cast<uLongf>(planes.size());
  if (uncompress(planes.data(), &planes_size, packed_.data(), static_cast<uLong>(packed_.size())) != Z_OK ||
      planes_size != planes.size()) {
    throw std::logic_error("CompactPoints: the packed coordinates do not inflate to their size");
  }
  points.resize(n);
  for (int a = 0; a < 3; ++a) {
    std::uint16_t value = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const auto difference = static_cast<std::uint16_t>(
          planes[(2 * static_cast<std::size_t>(a)) * n + i] |
          (static_cast<std::uint16_t>(planes[(2 * static_cast<std::size_t>(a) + 1) * n + i]) << 8));
      value = static_cast<std::uint16_t>(value + difference);
      points[i](a) = step_ * static_cast<float>(static_cast<std::int16_t>(value));
    }
  }
  return points;
}

}  // namespace unimap::map
