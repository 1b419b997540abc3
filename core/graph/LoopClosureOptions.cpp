#include "graph/LoopClosureOptions.hpp"

#include <algorithm>

#include <cmath>

namespace unimap::graph {

namespace {

constexpr double kPi = 3.14159265358979323846;

bool Positive(double value) { return std::isfinite(value) && value > 0.0; }
bool NonNegative(double value) { return std::isfinite(value) && value >= 0.0; }
bool Fraction(double value) { return std::isfinite(value) && value >= 0.0 && value <= 1.0; }

bool Fail(std::string* why, const char* reason) {
  if (why != nullptr) *why = reason;
  return false;
}

}  // namespace

bool LoopClosureOptions::IsValid(std::string* why) const {
  if (!Positive(search_resolution_m) || !Positive(search_kernel_m) || !Positive(fine_resolution_m) ||
      !Positive(fine_clamp_m)) {
    return Fail(why, "search_resolution_m, search_kernel_m, fine_resolution_m and fine_clamp_m must be positive");
  }
  if (search_kernel_m > 10.0 * search_resolution_m) {
    return Fail(why, "search_kernel_m must be at most 10 search_resolution_m");
  }
  if (search_levels < 1 || search_levels > 8) return Fail(why, "search_levels must be in [1, 8]");
  if (fine_clamp_m > 10.0 * fine_resolution_m) return Fail(why, "fine_clamp_m must be at most 10 fine_resolution_m");
  if (!Positive(normal_cell_m) || !Fraction(planarity_ratio)) {
    return Fail(why, "normal_cell_m must be positive and planarity_ratio in [0, 1]");
  }
  if (fine_clamp_m < fine_resolution_m) return Fail(why, "fine_clamp_m must be at least fine_resolution_m");
  if (!NonNegative(search_voxel_m) || !NonNegative(refine_voxel_m)) {
    return Fail(why, "search_voxel_m and refine_voxel_m must be >= 0");
  }
  if (max_search_points < 10 || max_refine_points < 10 || min_scan_points < 1 || min_scan_points > max_refine_points) {
    return Fail(why,
                "max_search_points and max_refine_points must be >= 10, min_scan_points in [1, max_refine_points]");
  }
  if (!NonNegative(z_window_m) || !NonNegative(yaw_window_rad) || yaw_window_rad > kPi) {
    return Fail(why, "z_window_m must be >= 0 and yaw_window_rad in [0, pi]");
  }
  if (!Positive(min_yaw_step_rad) || !Positive(max_yaw_step_rad) || min_yaw_step_rad > max_yaw_step_rad) {
    return Fail(why, "min_yaw_step_rad and max_yaw_step_rad must be positive, min <= max");
  }
  if (!NonNegative(ambiguity_margin_m)) return Fail(why, "ambiguity_margin_m must be >= 0");
  if (max_candidates < 2) return Fail(why, "max_candidates must be at least 2 (the best and an alternative)");
  if (!Fraction(min_search_score) || !Fraction(candidate_score_ratio)) {
    return Fail(why, "min_search_score and candidate_score_ratio must be in [0, 1]");
  }
  if (max_iterations < 1) return Fail(why, "max_iterations must be at least 1");
  if (!Positive(huber_m)) return Fail(why, "huber_m must be positive");
  if (!Positive(inlier_distance_m) || inlier_distance_m > fine_clamp_m) {
    return Fail(why, "inlier_distance_m must be positive and at most fine_clamp_m");
  }
  if (!Fraction(min_score) || !Fraction(max_ambiguity)) {
    return Fail(why, "min_score and max_ambiguity must be in [0, 1]");
  }
  if (!Positive(ambiguity_floor) || ambiguity_floor > 1.0) return Fail(why, "ambiguity_floor must be in (0, 1]");
  if (!Positive(distinct_translation_m) || !Positive(distinct_rotation_rad)) {
    return Fail(why, "distinct_translation_m and distinct_rotation_rad must be positive");
  }
  if (!Positive(max_position_sigma_m) || !Positive(max_rotation_sigma_rad)) {
    return Fail(why, "max_position_sigma_m and max_rotation_sigma_rad must be positive");
  }
  if (!Positive(effective_points)) return Fail(why, "effective_points must be positive");
  if (!NonNegative(min_sigma_position_m) || !NonNegative(min_sigma_rotation_rad)) {
    return Fail(why, "min_sigma_position_m and min_sigma_rotation_rad must be >= 0");
  }
  return true;
}

LoopClosureOptions LoopClosureOptions::ForVoxel(double voxel_m) {
  LoopClosureOptions o;
  const double fine = std::max(1.0, voxel_m / o.fine_resolution_m);
  o.fine_resolution_m *= fine;
  o.fine_clamp_m *= fine;
  o.normal_cell_m *= fine;
  o.refine_voxel_m *= fine;
  o.huber_m *= fine;
  o.inlier_distance_m *= fine;
  const double coarse = std::max(1.0, voxel_m / o.search_resolution_m);
  o.search_resolution_m *= coarse;
  o.search_kernel_m *= coarse;
  o.search_voxel_m *= coarse;
  return o;
}

void LoopClosureOptions::VisitFields(options::FieldVisitor& v) {
  v.Field("search_resolution_m", &search_resolution_m, "m");
  v.Field("search_kernel_m", &search_kernel_m, "m");
  v.Field("search_levels", &search_levels, "count");
  v.Field("fine_resolution_m", &fine_resolution_m, "m");
  v.Field("fine_clamp_m", &fine_clamp_m, "m");
  v.Field("normal_cell_m", &normal_cell_m, "m");
  v.Field("planarity_ratio", &planarity_ratio, "");
  v.Field("search_voxel_m", &search_voxel_m, "m");
  v.Field("max_search_points", &max_search_points, "count");
  v.Field("refine_voxel_m", &refine_voxel_m, "m");
  v.Field("max_refine_points", &max_refine_points, "count");
  v.Field("min_scan_points", &min_scan_points, "count");
  v.Field("seed", &seed, "");
  v.Field("z_window_m", &z_window_m, "m");
  v.Field("yaw_window_rad", &yaw_window_rad, "rad");
  v.Field("min_yaw_step_rad", &min_yaw_step_rad, "rad");
  v.Field("max_yaw_step_rad", &max_yaw_step_rad, "rad");
  v.Field("ambiguity_margin_m", &ambiguity_margin_m, "m");
  v.Field("max_candidates", &max_candidates, "count");
  v.Field("min_search_score", &min_search_score, "");
  v.Field("candidate_score_ratio", &candidate_score_ratio, "");
  v.Field("max_iterations", &max_iterations, "count");
  v.Field("huber_m", &huber_m, "m");
  v.Field("inlier_distance_m", &inlier_distance_m, "m");
  v.Field("min_score", &min_score, "");
  v.Field("distinct_translation_m", &distinct_translation_m, "m");
  v.Field("distinct_rotation_rad", &distinct_rotation_rad, "rad");
  v.Field("ambiguity_floor", &ambiguity_floor, "");
  v.Field("max_ambiguity", &max_ambiguity, "");
  v.Field("max_position_sigma_m", &max_position_sigma_m, "m");
  v.Field("max_rotation_sigma_rad", &max_rotation_sigma_rad, "rad");
  v.Field("effective_points", &effective_points, "");
  v.Field("min_sigma_position_m", &min_sigma_position_m, "m");
  v.Field("min_sigma_rotation_rad", &min_sigma_rotation_rad, "rad");
}

}  // namespace unimap::graph
