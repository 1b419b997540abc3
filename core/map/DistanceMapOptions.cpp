#include "map/DistanceMapOptions.hpp"

#include <cmath>

namespace unimap::map {

namespace {

bool Fail(std::string* why, const std::string& reason) {
  if (why != nullptr) *why = reason;
  return false;
}

bool PositiveFinite(double value) { return std::isfinite(value) && value > 0.0; }

}  // namespace

bool DistanceMapOptions::IsValid(std::string* why) const {
  if (!PositiveFinite(resolution_m)) return Fail(why, "resolution_m must be positive and finite");
  if (!PositiveFinite(max_range_m) || max_range_m < 2.0 * resolution_m) {
    return Fail(why, "max_range_m must be finite and at least two voxels (2 * resolution_m)");
  }
  if (!PositiveFinite(clamp_distance_m) || clamp_distance_m < resolution_m || clamp_distance_m > max_range_m) {
    return Fail(why, "clamp_distance_m must lie in [resolution_m, max_range_m]");
  }
  if (!(recenter_fraction > 0.0 && recenter_fraction <= 1.0)) {
    return Fail(why, "recenter_fraction must lie in (0, 1]");
  }
  if (!(std::isfinite(growth_margin_m) && growth_margin_m >= 0.0)) {
    return Fail(why, "growth_margin_m must be finite and non-negative");
  }
  if (max_edt_cells < 1000) return Fail(why, "max_edt_cells must be at least 1000");
  if (max_occupied_voxels < 1) return Fail(why, "max_occupied_voxels must be at least 1");
  if (!PositiveFinite(max_insert_range_m)) {
    return Fail(why, "max_insert_range_m must be positive and finite");
  }
  if (!(std::isfinite(coarse_beyond_m) && coarse_beyond_m >= 0.0)) {
    return Fail(why, "coarse_beyond_m must be finite and non-negative (0: off)");
  }
  if (!(prob_hit > 0.5 && prob_hit < 1.0)) return Fail(why, "prob_hit must lie in (0.5, 1)");
  if (!(prob_miss > 0.0 && prob_miss < 0.5)) return Fail(why, "prob_miss must lie in (0, 0.5)");
  if (!(clamp_min_probability > 0.0 && clamp_min_probability < occupancy_threshold &&
        occupancy_threshold < clamp_max_probability && clamp_max_probability < 1.0)) {
    return Fail(why, "need 0 < clamp_min_probability < occupancy_threshold < clamp_max_probability < 1");
  }
  // Octree keys are 16 bit: coordinates must stay within +-32768 voxels.
  const double key_half_range_m = 32768.0 * resolution_m;
  if (max_range_m + max_insert_range_m >= 0.5 * key_half_range_m) {
    return Fail(why, "max_range_m + max_insert_range_m must be below 16384 voxels (octree key range)");
  }
  return true;
}

void DistanceMapOptions::VisitFields(options::FieldVisitor& v) {
  v.SetElsewhere("resolution_m", "the platform parameter distance_map_resolution_m");
  v.SetElsewhere("max_range_m", "the platform parameter distance_map_max_range_m");
  v.Field("clamp_distance_m", &clamp_distance_m, "m");
  v.Field("recenter_fraction", &recenter_fraction, "");
  v.SetElsewhere("follow_sensor", "the mapper (each submap's box)");
  v.Field("growth_margin_m", &growth_margin_m, "m");
  v.Field("max_edt_cells", &max_edt_cells, "count");
  v.Field("max_occupied_voxels", &max_occupied_voxels, "count");
  v.Field("max_insert_range_m", &max_insert_range_m, "m");
  v.Field("coarse_beyond_m", &coarse_beyond_m, "m");
  v.Field("raycast_free_space", &raycast_free_space, "");
  v.Field("clear_occupied_only", &clear_occupied_only, "");
  v.Field("discretize_rays", &discretize_rays, "");
  v.Field("prob_hit", &prob_hit, "");
  v.Field("prob_miss", &prob_miss, "");
  v.Field("occupancy_threshold", &occupancy_threshold, "");
  v.Field("clamp_min_probability", &clamp_min_probability, "");
  v.Field("clamp_max_probability", &clamp_max_probability, "");
  v.SetElsewhere("compute_distances", "the mapper (each submap's own)");
  v.Field("subvoxel_surfaces", &subvoxel_surfaces, "");
  v.Field("signed_surfaces", &signed_surfaces, "");
  v.Field("cell_planes", &cell_planes, "");
}

}  // namespace unimap::map
