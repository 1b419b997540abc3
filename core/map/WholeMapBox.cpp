#include "map/WholeMapBox.hpp"

#include <algorithm>
#include <cmath>

namespace unimap::map {

std::optional<DistanceMapOptions> WholeMapOptions(const std::vector<Eigen::Vector3f>& points_map,
                                                  const DistanceMapOptions& options,
                                                  const Eigen::Vector3f& centre_map) {
  if (points_map.empty() || !centre_map.allFinite()) return std::nullopt;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-HUGE_VAL);
  for (const Eigen::Vector3f& p : points_map) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p.cast<double>());
    hi = hi.cwiseMax(p.cast<double>());
  }
  if (!(lo.array() <= hi.array()).all()) return std::nullopt;
  // The planner's field box: occupied voxels inflated by the clamp (rounded
  // up to voxels), one voxel of slack per side for voxel alignment.
  const double res = options.resolution_m;
  const double pad = std::ceil(options.clamp_distance_m / res) * res + res;
  double cells = 1.0;
  for (int a = 0; a < 3; ++a) cells *= std::ceil((hi[a] - lo[a] + 2.0 * pad) / res);
  if (cells > 0.9 * static_cast<double>(options.max_edt_cells)) return std::nullopt;
  // Half-size of a box about the centre that reaches every point and its padding.
  const Eigen::Vector3d c = centre_map.cast<double>();
  const double reach = std::max((hi - c).maxCoeff(), (c - lo).maxCoeff()) + pad;
  DistanceMapOptions whole = options;
  whole.max_range_m = std::max(reach, options.max_range_m);
  whole.follow_sensor = false;
  if (!whole.IsValid(nullptr)) return std::nullopt;
  return whole;
}

}  // namespace unimap::map
