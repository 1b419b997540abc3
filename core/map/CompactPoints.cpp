#include "map/CompactPoints.hpp"

#include <algorithm>
#include <cmath>

namespace unimap::map {

CompactPoints::CompactPoints(const std::vector<Eigen::Vector3f>& points) {
  float extent = 0.0f;
  for (const Eigen::Vector3f& p : points) {
    if (p.allFinite()) extent = std::max(extent, p.cwiseAbs().maxCoeff());
  }
  step_ = std::max(kMinStep, extent / 32767.0f);
  coordinates_.reserve(points.size() * 3);
  for (const Eigen::Vector3f& p : points) {
    for (int a = 0; a < 3; ++a) {
      const float v = std::isfinite(p(a)) ? std::round(p(a) / step_) : 0.0f;
      coordinates_.push_back(static_cast<std::int16_t>(std::clamp(v, -32767.0f, 32767.0f)));
    }
  }
}

std::vector<Eigen::Vector3f> CompactPoints::Expand() const {
  std::vector<Eigen::Vector3f> points;
  points.reserve(size());
  for (std::size_t i = 0; i < coordinates_.size(); i += 3) {
    points.emplace_back(step_ * coordinates_[i], step_ * coordinates_[i + 1], step_ * coordinates_[i + 2]);
  }
  return points;
}

}  // namespace unimap::map
