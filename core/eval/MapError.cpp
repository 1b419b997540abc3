#include "eval/MapError.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "unimap/Errors.hpp"

namespace unimap::eval {

MapErrorStats ComputeMapError(const std::vector<Eigen::Vector3f>& points,
                              const std::function<double(const Eigen::Vector3d&)>& distance_to_truth_m) {
  if (points.empty()) throw InputError("map error: the map has no points");
  std::vector<double> distances(points.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) throw InputError("map error: point " + std::to_string(i) + " is not finite");
    const double d = distance_to_truth_m(points[i].cast<double>());
    if (!(d >= 0.0) || !std::isfinite(d)) {
      throw InputError("map error: point " + std::to_string(i) + " has no finite distance to the truth (" +
                       std::to_string(d) + ")");
    }
    distances[i] = d;
    sum += d;
  }
  const std::size_t n = distances.size();
  MapErrorStats stats;
  stats.points = n;
  stats.mean_m = sum / static_cast<double>(n);
  stats.max_m = *std::max_element(distances.begin(), distances.end());
  // Nearest rank ceil(0.95 n), 1-based, computed in integers (19 n / 20 rounded up).
  const std::size_t rank = (19 * n + 19) / 20;
  const auto p95 = distances.begin() + static_cast<std::ptrdiff_t>(rank - 1);
  std::nth_element(distances.begin(), p95, distances.end());
  stats.p95_m = *p95;
  return stats;
}

}  // namespace unimap::eval
