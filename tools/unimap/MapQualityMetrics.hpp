#pragma once
// The map's GT-free quality (eval::ComputeMapQuality, eval::FindLargestPlanes)
// as run.json's mapping objects and as metrics rows.
#include <vector>

#include "Json.hpp"
#include "eval/LargestPlanes.hpp"
#include "eval/MapQuality.hpp"
#include "eval/MetricRows.hpp"

namespace unimap::cli {

// {"mean_map_entropy", "mean_plane_variance_m2", "planar_share", "points_evaluated", "radius_m"}.
Json MapQualityJson(const eval::MapQuality& quality, const eval::MapQualityOptions& options = {});

// The same as metrics.json entries and display rows (map_mean_entropy, ...).
std::vector<eval::ExtraMetric> MapQualityMetrics(const eval::MapQuality& quality,
                                                 const eval::MapQualityOptions& options = {});

// The largest planes (eval::FindLargestPlanes), largest first, as an array
// of {"points", "normal", "offset_m", "thickness_m", "median_range_m"}.
Json LargestPlanesJson(const std::vector<eval::MapPlane>& planes);

// The same as metrics.json entries and display rows: map_plane_K_thickness_m,
// map_plane_K_median_range_m, map_plane_K_points and map_plane_K_normal_z for K = 1, 2, ...
std::vector<eval::ExtraMetric> LargestPlanesMetrics(const std::vector<eval::MapPlane>& planes);

// Both of a map's GT-free measures as metrics rows: MapQualityMetrics of
// its quality, then LargestPlanesMetrics of its largest planes.
std::vector<eval::ExtraMetric> MapMetricsWithoutTruth(const std::vector<Eigen::Vector3f>& points_map);

}  // namespace unimap::cli
