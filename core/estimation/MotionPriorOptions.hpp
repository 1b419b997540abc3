#pragma once
#include <string>

#include <Eigen/Core>

#include "options/FieldVisitor.hpp"

namespace unimap::estimation {

// Where the localiser's prediction between scans comes from.
enum class MotionSource {
  kImu,               // the ESKF integrates the IMU (default; the paper's method)
  kWheelOdometry,     // increments of the dataset's odometry.csv
  kConstantVelocity,  // the velocity of the last two localised poses
  kStatic,            // the body does not move: scans placed at the start pose, not matched
};

// Noise of the motion priors used without an IMU.
struct MotionPriorOptions {
  MotionSource source = MotionSource::kImu;  // see MotionSource
  bool static_body = false;                  // the platform's body never moves (a scanner on a fixed stand):
                                             // `unimap run` then picks kStatic whatever the data holds
  double odometry_sigma_per_m = 0.05;        // wheel odometry: position sigma per metre travelled
  double odometry_sigma_rad_per_rad = 0.05;  // wheel odometry: rotation sigma per radian turned
  double odometry_sigma_rad_per_m = 0.005;   // wheel odometry: rotation sigma per metre travelled
  double odometry_min_sigma_m = 0.005;       // wheel odometry: position sigma floor per step (m)
  double odometry_min_sigma_rad = 0.002;     // wheel odometry: rotation sigma floor per step (rad)
  double max_odometry_gap_s = 0.5;           // an odometry gap longer than this around a scan: no prediction
  double velocity_sigma_m_s = 1.0;           // constant velocity: unmodelled velocity change (m/s; 1 m/s
                                             // per 0.1 s sweep is a car braking or speeding up at 1 g)
  double rate_sigma_rad_s = 0.2;             // constant velocity: unmodelled angular-rate change (rad/s)
  double max_speed_m_s = 15.0;               // constant velocity, before a velocity is known: the fastest
                                             // expected speed, the prediction's spread (m/s)
  double max_rate_rad_s = 1.0;               // ... and turn rate (rad/s)

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  // True when every field is in range; otherwise false with the reason in *why.
  bool IsValid(std::string* why) const;
};

// Covariance of [dp, dtheta] after dt seconds of motion unmodelled at the
// constant-velocity sigmas: diag((velocity_sigma_m_s dt)^2 x3, (rate_sigma_rad_s dt)^2 x3).
Eigen::Matrix<double, 6, 6> UnmodeledMotionCovariance(const MotionPriorOptions& options, double dt);

// "imu", "odometry", "constant-velocity", "static"; false for anything else.
bool ParseMotionSource(const std::string& text, MotionSource* source);

}  // namespace unimap::estimation
