#include "calibration/CalibrationOptions.hpp"

namespace unimap::calibration {
namespace {

bool Fail(std::string* why, const char* text) {
  if (why) *why = text;
  return false;
}

}  // namespace

bool CalibrationOptions::IsValid(std::string* why) const {
  if (!(neighbourhood_radius_m > 0.0)) return Fail(why, "neighbourhood_radius_m must be > 0");
  if (min_neighbours < 3) return Fail(why, "min_neighbours must be >= 3");
  if (max_neighbours < min_neighbours) return Fail(why, "max_neighbours must be >= min_neighbours");
  if (max_measured < 1) return Fail(why, "max_measured must be >= 1");
  if (!(max_plane_sigmas > 0.0)) return Fail(why, "max_plane_sigmas must be > 0");
  if (!(huber_sigmas > 0.0)) return Fail(why, "huber_sigmas must be > 0");
  if (!(min_view_angle_deg >= 0.0 && min_view_angle_deg < 180.0))
    return Fail(why, "min_view_angle_deg must be in [0, 180)");
  if (!(min_view_distance_m >= 0.0)) return Fail(why, "min_view_distance_m must be >= 0");
  if (!(planar_ratio > 0.0 && planar_ratio < 1.0)) return Fail(why, "planar_ratio must be in (0, 1)");
  if (!(min_spread_ratio >= 0.0 && min_spread_ratio < 1.0)) return Fail(why, "min_spread_ratio must be in [0, 1)");
  if (max_neighbourhoods < 1) return Fail(why, "max_neighbourhoods must be >= 1");
  if (!(sigma_m > 0.0)) return Fail(why, "sigma_m must be > 0");
  if (!(prior_sigma_translation_m > 0.0) || !(prior_sigma_rotation_deg > 0.0))
    return Fail(why, "prior_sigma_translation_m and prior_sigma_rotation_deg must be > 0");
  if (!(max_correction_sigmas > 0.0)) return Fail(why, "max_correction_sigmas must be > 0");
  if (!(min_information_ratio > 0.0)) return Fail(why, "min_information_ratio must be > 0");
  if (max_rounds < 1 || max_iterations < 1) return Fail(why, "max_rounds and max_iterations must be >= 1");
  if (!(tolerance_translation_m >= 0.0) || !(tolerance_rotation_deg >= 0.0))
    return Fail(why, "tolerance_translation_m and tolerance_rotation_deg must be >= 0");
  return true;
}

}  // namespace unimap::calibration
