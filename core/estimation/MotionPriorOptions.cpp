#include "estimation/MotionPriorOptions.hpp"

#include <cmath>

namespace unimap::estimation {

bool MotionPriorOptions::IsValid(std::string* why) const {
  const double values[] = {
      odometry_sigma_per_m,   odometry_sigma_rad_per_rad, odometry_sigma_rad_per_m, odometry_min_sigma_m,
      odometry_min_sigma_rad, velocity_sigma_m_s,         rate_sigma_rad_s,         max_speed_m_s,
      max_rate_rad_s};
  for (double v : values) {
    if (!(v >= 0.0) || !std::isfinite(v)) {
      if (why != nullptr) *why = "motion prior sigmas must be finite and >= 0";
      return false;
    }
  }
  if (!(max_speed_m_s > 0.0) || !(max_rate_rad_s > 0.0)) {
    if (why != nullptr) *why = "max_speed_m_s and max_rate_rad_s must be > 0";
    return false;
  }
  if (!(odometry_min_sigma_m > 0.0) || !(odometry_min_sigma_rad > 0.0)) {
    if (why != nullptr) *why = "odometry_min_sigma_m and odometry_min_sigma_rad must be > 0";
    return false;
  }
  if (!(max_odometry_gap_s > 0.0)) {
    if (why != nullptr) *why = "max_odometry_gap_s must be > 0";
    return false;
  }
  return true;
}

Eigen::Matrix<double, 6, 6> UnmodeledMotionCovariance(const MotionPriorOptions& options, double dt) {
  const double sigma_p = options.velocity_sigma_m_s * dt;
  const double sigma_r = options.rate_sigma_rad_s * dt;
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();
  covariance.diagonal() << Eigen::Vector3d::Constant(sigma_p * sigma_p), Eigen::Vector3d::Constant(sigma_r * sigma_r);
  return covariance;
}

bool ParseMotionSource(const std::string& text, MotionSource* source) {
  if (text == "imu") {
    *source = MotionSource::kImu;
  } else if (text == "odometry") {
    *source = MotionSource::kWheelOdometry;
  } else if (text == "constant-velocity") {
    *source = MotionSource::kConstantVelocity;
  } else if (text == "static") {
    *source = MotionSource::kStatic;
  } else {
    return false;
  }
  return true;
}

void MotionPriorOptions::VisitFields(options::FieldVisitor& v) {
  v.SetElsewhere("source", "the dataset's streams or `unimap run --motion`");
  v.Field("static_body", &static_body, "");
  v.Field("odometry_sigma_per_m", &odometry_sigma_per_m, "m/m");
  v.Field("odometry_sigma_rad_per_rad", &odometry_sigma_rad_per_rad, "rad/rad");
  v.Field("odometry_sigma_rad_per_m", &odometry_sigma_rad_per_m, "rad/m");
  v.Field("odometry_min_sigma_m", &odometry_min_sigma_m, "m");
  v.Field("odometry_min_sigma_rad", &odometry_min_sigma_rad, "rad");
  v.Field("max_odometry_gap_s", &max_odometry_gap_s, "s");
  v.Field("velocity_sigma_m_s", &velocity_sigma_m_s, "m/s");
  v.Field("rate_sigma_rad_s", &rate_sigma_rad_s, "rad/s");
  v.Field("max_speed_m_s", &max_speed_m_s, "m/s");
  v.Field("max_rate_rad_s", &max_rate_rad_s, "rad/s");
}

}  // namespace unimap::estimation
