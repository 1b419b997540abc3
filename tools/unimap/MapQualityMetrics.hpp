#pragma once
// The map's GT-free quality (eval::ComputeMapQuality) as run.json's
// mapping.map_quality object and as metrics rows.
#include <vector>

#include "Json.hpp"
#include "eval/MapQuality.hpp"
#include "eval/MetricRows.hpp"

namespace unimap::cli {

// {"mean_map_entropy", "mean_plane_variance_m2", "planar_share", "points_evaluated", "radius_m"}.
Json MapQualityJson(const eval::MapQuality& quality, const eval::MapQualityOptions& options = {});

// The same as metrics.json entries and display rows (map_mean_entropy, ...).
std::vector<eval::ExtraMetric> MapQualityMetrics(const eval::MapQuality& quality,
                                                 const eval::MapQualityOptions& options = {});

}  // namespace unimap::cli
