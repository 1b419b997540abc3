#pragma once
#include <string>

#include <Eigen/Geometry>

#include "unimap/OdometrySample.hpp"

namespace unimap::estimation {

// A relative body motion and its uncertainty.
struct MotionPrediction {
  bool ok = false;                                                               // false: no prediction (see reason)
  std::string reason;                                                            // why not
  Eigen::Isometry3d T_prev_next = Eigen::Isometry3d::Identity();                 // body at t1 in the body frame at t0
  Eigen::Matrix<double, 6, 6> covariance = Eigen::Matrix<double, 6, 6>::Zero();  // of [dp, dtheta], body frame at t0
};

// Predicts the body's motion between scans for data without an IMU (the
// localiser's other motion sources, docs/design.md 1.2): wheel-odometry
// increments or a constant-velocity model. Not thread-safe.
class MotionPrior {
 public:
  virtual ~MotionPrior() = default;
  // A wheel-odometry reading (priors that do not use odometry ignore it).
  virtual void AddOdometry(const OdometrySample& sample) = 0;
  // True when Predict can cover the interval ending at time_s.
  virtual bool ReadyFor(double time_s) const = 0;
  // The body motion from t0 to t1 (t1 >= t0) and its covariance.
  virtual MotionPrediction Predict(double t0, double t1) const = 0;
  // The localised pose at time_s (a constant-velocity prior learns its velocity from these).
  virtual void Observe(double time_s, const Eigen::Isometry3d& T_world_body) = 0;
};

}  // namespace unimap::estimation
