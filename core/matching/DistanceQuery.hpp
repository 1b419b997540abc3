#pragma once
#include <Eigen/Core>

namespace unimap::matching {

// Distance from a point (map frame) to the nearest occupied surface,
// clamped by the implementation. Implementations must be thread-safe for
// concurrent reads.
class DistanceQuery {
 public:
  virtual ~DistanceQuery() = default;
  // Distances of n points, written to out[0..n).
  virtual void Distances(const Eigen::Vector3f* points_map, int n, float* out) const = 0;
};

}  // namespace unimap::matching
