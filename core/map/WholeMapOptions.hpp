#pragma once
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "map/DistanceMapOptions.hpp"

namespace unimap::map {

// For a fixed prior map: options whose one distance box, centred at
// center_map, holds every point of the map plus the clamp distance and never
// moves (follow_sensor false), so the distance transform is computed once
// instead of on every recentring. std::nullopt when FieldBoxPlanner would
// have to shrink that box to options.max_edt_cells, or when the box or the
// centre leave the octree's key range; the box then follows the sensor.
std::optional<DistanceMapOptions> WholeMapOptions(const std::vector<Eigen::Vector3f>& points_map,
                                                  const DistanceMapOptions& options, const Eigen::Vector3f& center_map);

}  // namespace unimap::map
