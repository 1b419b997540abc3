#include "MapQualityMetrics.hpp"

#include <string>

#include "TextFormat.hpp"

namespace unimap::cli {

Json MapQualityJson(const eval::MapQuality& quality, const eval::MapQualityOptions& options) {
  Json o = Json::object();
  const bool defined = quality.evaluated > 0;
  o["mean_map_entropy"] = defined ? Json(quality.mean_map_entropy) : Json(nullptr);
  o["mean_plane_variance_m2"] = defined ? Json(quality.mean_plane_variance_m2) : Json(nullptr);
  o["planar_share"] = defined ? Json(quality.planar_share) : Json(nullptr);
  o["points_evaluated"] = quality.evaluated;
  o["radius_m"] = options.radius_m;
  return o;
}

std::vector<eval::ExtraMetric> MapQualityMetrics(const eval::MapQuality& quality,
                                                 const eval::MapQualityOptions& options) {
  const bool defined = quality.evaluated > 0;
  const auto value = [&](double v) { return defined ? Json(v) : Json(nullptr); };
  const auto shown = [&](double v, int decimals) { return defined ? Fixed(v, decimals) : std::string("n/a"); };
  const std::string radius = Fixed(options.radius_m, 2);
  return {
      {value(quality.mean_map_entropy),
       {"map_mean_entropy", shown(quality.mean_map_entropy, 3),
        "mean map entropy: mean 0.5 ln det(2 pi e Sigma) of the points within " + radius +
            " m of each map point (no ground truth; lower is crisper)"}},
      {value(quality.mean_plane_variance_m2),
       {"map_plane_variance_m2", shown(quality.mean_plane_variance_m2, 6),
        "mean plane variance: mean smallest eigenvalue of that Sigma (a surface's thickness squared), m^2"}},
      {value(quality.planar_share),
       {"map_planar_share", shown(quality.planar_share, 3),
        "share of map points whose neighbourhood is planar (smallest eigenvalue <= 0.1 x the middle one)"}},
      {Json(quality.evaluated), {"map_quality_points", std::to_string(quality.evaluated), "map points evaluated"}},
  };
}

}  // namespace unimap::cli
