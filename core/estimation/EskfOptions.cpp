#include "estimation/EskfOptions.hpp"

#include <cmath>

namespace unimap::estimation {

bool EskfOptions::IsValid(std::string* why) const {
  std::string local_why;
  if (why == nullptr) why = &local_why;
  const double positive[] = {sigma_accel_m_s2,
                             sigma_gyro_rad_s,
                             gravity_m_s2,
                             initial_sigma_position_m,
                             initial_sigma_velocity_m_s,
                             initial_sigma_attitude_rad,
                             initial_sigma_accel_bias_m_s2,
                             initial_sigma_gyro_bias_rad_s,
                             max_imu_gap_s};
  for (const double value : positive) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      *why = "noise sigmas, initial sigmas, gravity and max_imu_gap_s must be positive and finite";
      return false;
    }
  }
  if (!(accel_bias_walk_m_s2_sqrt_s >= 0.0) || !(gyro_bias_walk_rad_s_sqrt_s >= 0.0)) {
    *why = "bias random walks must be non-negative";
    return false;
  }
  return true;
}

void EskfOptions::VisitFields(options::FieldVisitor& v) {
  v.SetElsewhere("sigma_accel_m_s2", "the platform parameter sigma_accel_m_s2");
  v.SetElsewhere("sigma_gyro_rad_s", "the platform parameter sigma_gyro_rad_s");
  v.Field("accel_bias_walk_m_s2_sqrt_s", &accel_bias_walk_m_s2_sqrt_s, "m/s^2/sqrt(s)");
  v.Field("gyro_bias_walk_rad_s_sqrt_s", &gyro_bias_walk_rad_s_sqrt_s, "rad/s/sqrt(s)");
  v.Field("gravity_m_s2", &gravity_m_s2, "m/s^2");
  v.Field("initial_sigma_position_m", &initial_sigma_position_m, "m");
  v.Field("initial_sigma_velocity_m_s", &initial_sigma_velocity_m_s, "m/s");
  v.Field("initial_sigma_attitude_rad", &initial_sigma_attitude_rad, "rad");
  v.Field("initial_sigma_accel_bias_m_s2", &initial_sigma_accel_bias_m_s2, "m/s^2");
  v.Field("initial_sigma_gyro_bias_rad_s", &initial_sigma_gyro_bias_rad_s, "rad/s");
  v.Field("max_imu_gap_s", &max_imu_gap_s, "s");
}

}  // namespace unimap::estimation
