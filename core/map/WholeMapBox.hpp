#pragma once
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "map/DistanceMapOptions.hpp"

namespace unimap::map {

// For a fixed prior map: options whose one distance box, centred at
// centre_map, holds every point of the map plus the clamp distance, and never
// moves (follow_sensor false), so the distance transform is computed once
// instead of on every recentring. std::nullopt when that box would exceed
// 90 % of options.max_edt_cells (the planner's own inflation must still fit)
// or the octree's key range; the box then follows the sensor as usual.
std::optional<DistanceMapOptions> WholeMapOptions(const std::vector<Eigen::Vector3f>& points_map,
                                                  const DistanceMapOptions& options,
                                                  const Eigen::Vector3f& centre_map);

}  // namespace unimap::map
