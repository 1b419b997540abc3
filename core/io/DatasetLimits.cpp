#include "io/DatasetLimits.hpp"

#include <cmath>
#include <cstdio>

#include "io/NumberText.hpp"

namespace unimap::io {
namespace {

// A limit as shown in messages: 4 significant digits.
std::string Limit(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.4g", value);
  return buffer;
}

// "<what> <axis> <value> <unit> is beyond +-<limit> <unit>" for the first
// component of v outside [-limit, limit] (NaN included); empty otherwise.
std::string Beyond(const char* what, const Eigen::Vector3d& v, double limit, const char* unit) {
  for (int i = 0; i < 3; ++i) {
    if (std::abs(v[i]) <= limit) continue;
    return std::string(what) + " " + "xyz"[i] + " " + NumberString(v[i]) + " " + unit + " is " +
           (std::isnan(v[i]) ? std::string("not a number") : "beyond +-" + Limit(limit) + " " + unit);
  }
  return {};
}

}  // namespace

DatasetLimits DatasetLimits::Unlimited() {
  DatasetLimits none;
  for (double* limit : {&none.max_accel_m_s2, &none.max_gyro_rad_s, &none.max_encoder_angle_rad, &none.max_position_m,
                        &none.max_abs_time_s, &none.max_imu_step_s, &none.max_encoder_step_s, &none.max_scan_step_s,
                        &none.max_odometry_step_s, &none.max_scan_duration_s}) {
    *limit = HUGE_VAL;
  }
  none.check_line_geometry = false;
  return none;
}

bool DatasetLimits::IsValid(std::string* why) const {
  for (const double limit :
       {max_accel_m_s2, max_gyro_rad_s, max_encoder_angle_rad, max_position_m, max_abs_time_s, max_imu_step_s,
        max_encoder_step_s, max_scan_step_s, max_odometry_step_s, max_scan_duration_s}) {
    if (!(limit > 0.0)) {
      if (why != nullptr) *why = "every dataset limit must be positive";
      return false;
    }
  }
  return true;
}

std::string DatasetLimits::ImuProblem(const ImuSample& sample) const {
  std::string problem = Beyond("accelerometer", sample.accel_m_s2, max_accel_m_s2, "m/s^2");
  if (problem.empty()) problem = Beyond("gyroscope", sample.gyro_rad_s, max_gyro_rad_s, "rad/s");
  return problem;
}

std::string DatasetLimits::EncoderProblem(const EncoderSample& sample) const {
  if (std::abs(sample.angle_rad) <= max_encoder_angle_rad) return {};
  return "encoder angle " + NumberString(sample.angle_rad) + " rad is " +
         (std::isnan(sample.angle_rad) ? std::string("not a number")
                                       : "beyond +-" + Limit(max_encoder_angle_rad) + " rad");
}

std::string DatasetLimits::PositionProblem(const Eigen::Vector3d& position_m) const {
  return Beyond("position", position_m, max_position_m, "m");
}

std::string DatasetLimits::ScanProblem(const ScanRecord& scan) const {
  const double start_s = ScanStartTime(scan);
  const double duration_s = ScanEndTime(scan) - start_s;
  if (!(std::abs(start_s) <= max_abs_time_s)) {
    return "scan start time " + NumberString(start_s) + " s is beyond +-" + Limit(max_abs_time_s) + " s";
  }
  if (!(std::abs(duration_s) <= max_scan_duration_s)) {
    return "scan lasts " + NumberString(duration_s) + " s, longer than " + Limit(max_scan_duration_s) + " s";
  }
  const auto* line = std::get_if<LineScan>(&scan);
  if (line != nullptr && check_line_geometry) {
    if (!std::isfinite(line->angle_min_rad) || !std::isfinite(line->angle_increment_rad)) {
      return "line scan angle_min_rad / angle_increment_rad are not finite";
    }
    if (!(line->range_min_m >= 0.0) || !(line->range_max_m >= line->range_min_m)) {
      return "line scan range limits [" + NumberString(line->range_min_m) + ", " + NumberString(line->range_max_m) +
             "] m are not 0 <= range_min_m <= range_max_m";
    }
  }
  return {};
}

}  // namespace unimap::io
