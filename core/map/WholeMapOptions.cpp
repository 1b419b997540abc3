#include "map/WholeMapOptions.hpp"

#include <algorithm>
#include <cmath>

#include "map/FieldBoxPlanner.hpp"
#include "map/KeyBox.hpp"
#include "map/OccupancyTree.hpp"

namespace unimap::map {
namespace {

// Octree keys are voxel indices (offset by a constant that sizes ignore).
Eigen::Vector3i KeyOf(const Eigen::Vector3d& p, double resolution_m) {
  return (p / resolution_m).array().floor().cast<int>();
}

}  // namespace

std::optional<DistanceMapOptions> WholeMapOptions(const std::vector<Eigen::Vector3f>& points_map,
                                                  const DistanceMapOptions& options,
                                                  const Eigen::Vector3f& center_map) {
  if (points_map.empty() || !center_map.allFinite()) return std::nullopt;
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(HUGE_VAL);
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-HUGE_VAL);
  for (const Eigen::Vector3f& p : points_map) {
    if (!p.allFinite()) continue;
    lo = lo.cwiseMin(p.cast<double>());
    hi = hi.cwiseMax(p.cast<double>());
  }
  if (!(lo.array() <= hi.array()).all()) return std::nullopt;
  const double res = options.resolution_m;
  const Eigen::Vector3d c = center_map.cast<double>();
  // Half-size reaching every point, its clamp inflation and a voxel of slack.
  const double pad = std::ceil(options.clamp_distance_m / res) * res + res;
  const double reach = std::max((hi - c).maxCoeff(), (c - lo).maxCoeff()) + pad;
  DistanceMapOptions whole = options;
  whole.max_range_m = std::max(reach, options.max_range_m);
  whole.follow_sensor = false;
  if (!whole.IsValid(nullptr)) return std::nullopt;
  // DistanceMap::CheckPosition's key-range test for the centre.
  if (c.cwiseAbs().maxCoeff() + std::max(whole.max_range_m, whole.max_insert_range_m) >=
      OccupancyTree::HalfRangeM(res)) {
    return std::nullopt;
  }
  // The planner's own field box for the map's occupied keys (one voxel of
  // slack per side for rounding against the octree's keys).
  const FieldBoxPlanner planner(whole, res);
  const Eigen::Vector3i center_key = KeyOf(c, res);
  const KeyBox sensor_box = planner.SensorBox(center_key);
  const KeyBox occupied = KeyBox(KeyOf(lo, res), KeyOf(hi, res)).Inflated(1);
  if (!sensor_box.Contains(occupied)) return std::nullopt;
  bool shrunk = false;
  planner.FieldBox(occupied, sensor_box, center_key, &shrunk);
  if (shrunk) return std::nullopt;
  return whole;
}

}  // namespace unimap::map
