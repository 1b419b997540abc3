#include "calibration/PointGrid.hpp"

#include <algorithm>
#include <cmath>

namespace unimap::calibration {
namespace {

constexpr int kBits = 21;                  // per axis
constexpr int kOffset = 1 << (kBits - 1);  // cubes -2^20 .. 2^20 - 1 per axis
constexpr std::uint64_t kMask = (std::uint64_t{1} << kBits) - 1;

}  // namespace

PointGrid::PointGrid(const std::vector<Eigen::Vector3f>& points, double edge_m)
    : points_(points), inverse_edge_(1.0 / edge_m) {
  cells_.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    cells_.emplace_back(Pack(Cube(points[i])), static_cast<std::uint32_t>(i));
  }
  std::sort(cells_.begin(), cells_.end());
}

Eigen::Vector3i PointGrid::Cube(const Eigen::Vector3f& p) const {
  Eigen::Vector3i c;
  for (int a = 0; a < 3; ++a) c(a) = static_cast<int>(std::floor(static_cast<double>(p(a)) * inverse_edge_));
  return c;
}

std::uint64_t PointGrid::Pack(const Eigen::Vector3i& cube) {
  std::uint64_t packed = 0;
  for (int a = 0; a < 3; ++a) {
    const std::uint64_t v = static_cast<std::uint64_t>(std::clamp(cube(a) + kOffset, 0, (1 << kBits) - 1)) & kMask;
    packed |= v << (kBits * a);
  }
  return packed;
}

std::pair<std::size_t, std::size_t> PointGrid::Range(std::uint64_t packed) const {
  const auto first = std::lower_bound(cells_.begin(), cells_.end(), std::make_pair(packed, std::uint32_t{0}));
  auto last = first;
  while (last != cells_.end() && last->first == packed) ++last;
  return {static_cast<std::size_t>(first - cells_.begin()), static_cast<std::size_t>(last - cells_.begin())};
}

}  // namespace unimap::calibration
