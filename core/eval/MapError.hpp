#pragma once
// Map accuracy: how far the points of a built map lie from the true surfaces
// (docs/evaluation.md, section 4).
#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/Core>

namespace unimap::eval {

// Distances of map points to the nearest true surface, in metres.
struct MapErrorStats {
  double mean_m = 0.0;     // mean over the points of d_i
  double p95_m = 0.0;      // 95th percentile of d_i, nearest rank: d_(ceil(0.95 n)) of the sorted d
  double max_m = 0.0;      // max_i d_i
  std::size_t points = 0;  // n, the points evaluated (all of them)
};

// d_i = distance_to_truth_m(points[i]) for every point (in the frame the
// distance function expects: transform the points first when the map's frame
// differs), summarised as MapErrorStats. The percentile is the nearest-rank
// one: with d sorted ascending, p95 = d[ceil(0.95 n) - 1] (an actual
// distance, never interpolated; the max for n < 20). Throws InputError for
// no points, a non-finite point, or a distance that is negative or not
// finite (naming the point's index).
MapErrorStats ComputeMapError(const std::vector<Eigen::Vector3f>& points,
                              const std::function<double(const Eigen::Vector3d&)>& distance_to_truth_m);

}  // namespace unimap::eval
