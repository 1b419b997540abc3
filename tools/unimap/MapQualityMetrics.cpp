#include "MapQualityMetrics.hpp"

#include <string>
#include <utility>

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

Json LargestPlanesJson(const std::vector<eval::MapPlane>& planes) {
  Json a = Json::array();
  for (const eval::MapPlane& p : planes) {
    Json o = Json::object();
    o["points"] = p.points;
    o["normal"] = Json::array({p.normal.x(), p.normal.y(), p.normal.z()});
    o["offset_m"] = p.offset_m;
    o["thickness_m"] = p.thickness_m;
    o["median_range_m"] = p.median_range_m;
    a.push_back(std::move(o));
  }
  return a;
}

std::vector<eval::ExtraMetric> LargestPlanesMetrics(const std::vector<eval::MapPlane>& planes) {
  std::vector<eval::ExtraMetric> rows;
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const eval::MapPlane& p = planes[k];
    const std::string name = "map_plane_" + std::to_string(k + 1);
    const std::string which = "plane " + std::to_string(k + 1) + " of the largest (normal " + Fixed(p.normal.x(), 2) +
                              " " + Fixed(p.normal.y(), 2) + " " + Fixed(p.normal.z(), 2) + ", " +
                              Fixed(p.offset_m, 2) + " m from the origin)";
    rows.push_back({Json(p.thickness_m),
                    {name + "_thickness_m", Fixed(p.thickness_m, 4),
                     which + ": thickness, 1.4826 x the median distance of its points from it (m)"}});
    rows.push_back({Json(p.median_range_m),
                    {name + "_median_range_m", Fixed(p.median_range_m, 2),
                     which + ": median distance of its points from the map's origin (m)"}});
    rows.push_back({Json(p.points), {name + "_points", std::to_string(p.points), which + ": its map points"}});
    rows.push_back({Json(p.normal.z()),
                    {name + "_normal_z", Fixed(p.normal.z(), 2),
                     which + ": its normal's z component (0: a vertical surface, +-1: a horizontal one, where "
                             "the map's z is vertical)"}});
  }
  return rows;
}

std::vector<eval::ExtraMetric> MapMetricsWithoutTruth(const std::vector<Eigen::Vector3f>& points_map) {
  std::vector<eval::ExtraMetric> rows = MapQualityMetrics(eval::ComputeMapQuality(points_map));
  for (eval::ExtraMetric& m : LargestPlanesMetrics(eval::FindLargestPlanes(points_map))) rows.push_back(std::move(m));
  return rows;
}

}  // namespace unimap::cli
