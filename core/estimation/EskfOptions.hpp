#pragma once
#include <string>

#include "options/FieldVisitor.hpp"

namespace unimap::estimation {

// Noise model and initial uncertainty of the error-state Kalman filter.
struct EskfOptions {
  double sigma_accel_m_s2 = 0.02;                // accelerometer white noise per sample (m/s^2)
  double sigma_gyro_rad_s = 0.002;               // gyroscope white noise per sample (rad/s)
  double accel_bias_walk_m_s2_sqrt_s = 1e-4;     // accelerometer bias random walk (m/s^2 per sqrt(s))
  double gyro_bias_walk_rad_s_sqrt_s = 1e-5;     // gyroscope bias random walk (rad/s per sqrt(s))
  double gravity_m_s2 = 9.80665;                 // gravity magnitude, world -z
  double initial_sigma_position_m = 0.01;        // initial position standard deviation (m)
  double initial_sigma_velocity_m_s = 0.01;      // initial velocity standard deviation (m/s)
  double initial_sigma_attitude_rad = 0.01;      // initial attitude standard deviation (rad)
  double initial_sigma_accel_bias_m_s2 = 0.05;   // initial accelerometer bias standard deviation
  double initial_sigma_gyro_bias_rad_s = 0.005;  // initial gyroscope bias standard deviation
  double max_imu_gap_s = 0.1;                    // longer gaps between IMU samples are input errors

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  bool IsValid(std::string* why) const;
};

}  // namespace unimap::estimation
