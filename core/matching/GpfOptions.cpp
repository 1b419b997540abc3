#include "matching/GpfOptions.hpp"

namespace unimap::matching {

bool GpfOptions::IsValid(std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  if (num_particles < 10) {
    *why = "num_particles must be at least 10";
    return false;
  }
  if (!(point_sigma_m > 0.0) || !(clamp_distance_m > 0.0) || !(voxel_size_m >= 0.0) || !(effective_points > 0.0)) {
    *why = "point_sigma_m, clamp_distance_m and effective_points must be positive, voxel_size_m >= 0";
    return false;
  }
  if (max_points < 0 || threads < 1 || refine_iterations < 0) {
    *why = "max_points and refine_iterations must be >= 0 and threads >= 1";
    return false;
  }
  if (!(min_sigma_position_m >= 0.0) || !(min_sigma_rotation_rad >= 0.0) ||
      !(min_information_ratio > 0.0 && min_information_ratio < 1.0)) {
    *why = "sigma floors must be >= 0 and min_information_ratio in (0, 1)";
    return false;
  }
  if (planes_only && !point_to_plane) {
    *why = "planes_only needs point_to_plane";
    return false;
  }
  return true;
}

void GpfOptions::VisitFields(options::FieldVisitor& v) {
  v.Field("num_particles", &num_particles, "count");
  v.Field("point_sigma_m", &point_sigma_m, "m");
  v.Field("clamp_distance_m", &clamp_distance_m, "m");
  v.Field("voxel_size_m", &voxel_size_m, "m");
  v.Field("max_points", &max_points, "count");
  v.Field("effective_points", &effective_points, "");
  v.Field("planar", &planar, "");
  v.Field("min_sigma_position_m", &min_sigma_position_m, "m");
  v.Field("min_sigma_rotation_rad", &min_sigma_rotation_rad, "rad");
  v.Field("min_information_ratio", &min_information_ratio, "");
  v.Field("refine_iterations", &refine_iterations, "count");
  v.SetElsewhere("point_to_plane", "`unimap run --plane-matching`");
  v.SetElsewhere("planes_only", "`unimap run --plane-matching`");
  v.SetElsewhere("threads", "`--threads`");
  v.SetElsewhere("seed", "`--seed`");
}

}  // namespace unimap::matching
