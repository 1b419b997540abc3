#include "pipeline/MapperOptions.hpp"

#include <cmath>

namespace unimap::pipeline {
namespace {

bool Fail(std::string* why, const std::string& reason) {
  if (why != nullptr) *why = reason;
  return false;
}

}  // namespace

bool LoopSearchOptions::IsValid(std::string* why) const {
  if (every_3d_scans < 1) return Fail(why, "loop_search.every_3d_scans must be >= 1");
  if (skip_recent_submaps < 0) return Fail(why, "loop_search.skip_recent_submaps must be >= 0");
  if (!(min_radius_m > 0.0) || !(max_radius_m >= min_radius_m) || !std::isfinite(max_radius_m)) {
    return Fail(why, "loop_search radii must satisfy 0 < min_radius_m <= max_radius_m (finite)");
  }
  if (!(radius_per_path_m >= 0.0) || !(submap_reach_m >= 0.0) || !(min_path_m >= 0.0)) {
    return Fail(why, "loop_search.radius_per_path_m, submap_reach_m and min_path_m must be >= 0");
  }
  if (max_candidates < 1 || max_cached_matchers < 1) {
    return Fail(why, "loop_search.max_candidates and max_cached_matchers must be >= 1");
  }
  if (!(redundant_overlap > 0.0 && redundant_overlap <= 1.0)) {
    return Fail(why, "loop_search.redundant_overlap must be in (0, 1]");
  }
  return true;
}

bool MapperOptions::IsValid(std::string* why) const {
  std::string reason;
  if (!localizer.IsValid(&reason)) return Fail(why, "localizer: " + reason);
  if (!submaps.IsValid(&reason)) return Fail(why, "submaps: " + reason);
  if (!graph.IsValid(&reason)) return Fail(why, "graph: " + reason);
  if (!loop_closure.IsValid(&reason)) return Fail(why, "loop_closure: " + reason);
  if (!loop_search.IsValid(&reason)) return Fail(why, reason);
  if (scans_3d_per_optimization < 1) return Fail(why, "scans_3d_per_optimization must be >= 1");
  if (!(scan_sigma_position_m > 0.0) || !(scan_sigma_rotation_rad > 0.0)) {
    return Fail(why, "scan_sigma_position_m and scan_sigma_rotation_rad must be > 0");
  }
  return true;
}

void MapperOptions::VisitFields(options::FieldVisitor& v) {
  localizer.VisitFields(v);
  v.SetElsewhere("submaps.scans_3d_per_submap", "the platform parameter scans_3d_per_submap");
  v.SetElsewhere("scans_3d_per_optimization", "the platform parameter scans_3d_per_optimization");
  v.Section("graph", [&] { graph.VisitFields(v); });
  v.Section("loop_closure", [&] { loop_closure.VisitFields(v); });
  v.Section("loop_search", [&] { loop_search.VisitFields(v); });
  v.Field("scan_sigma_position_m", &scan_sigma_position_m, "m");
  v.Field("scan_sigma_rotation_rad", &scan_sigma_rotation_rad, "rad");
  v.SetElsewhere("wait_for_background", "the run mode (offline or live)");
}

MapperOptions MapperOptions::FromPlatform(const CoreParameters& core) {
  MapperOptions o;
  o.localizer = LocalizerOptions::FromPlatform(core);
  o.submaps.scans_3d_per_submap = core.scans_3d_per_submap;
  o.submaps.map = o.localizer.map;
  o.loop_closure = graph::LoopClosureOptions::ForVoxel(core.distance_map_resolution_m);
  o.scans_3d_per_optimization = core.scans_3d_per_optimization;
  return o;
}

void LoopSearchOptions::VisitFields(options::FieldVisitor& v) {
  v.Field("enabled", &enabled, "");
  v.Field("every_3d_scans", &every_3d_scans, "count");
  v.Field("skip_recent_submaps", &skip_recent_submaps, "count");
  v.Field("min_radius_m", &min_radius_m, "m");
  v.Field("radius_per_path_m", &radius_per_path_m, "m/m");
  v.Field("max_radius_m", &max_radius_m, "m");
  v.Field("submap_reach_m", &submap_reach_m, "m");
  v.Field("max_candidates", &max_candidates, "count");
  v.Field("max_cached_matchers", &max_cached_matchers, "count");
  v.Field("min_path_m", &min_path_m, "m");
  v.Field("redundant_overlap", &redundant_overlap, "fraction");
}

}  // namespace unimap::pipeline
