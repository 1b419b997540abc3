#pragma once
#include <deque>

#include "estimation/MotionPrior.hpp"
#include "estimation/MotionPriorOptions.hpp"

namespace unimap::estimation {

// Wheel-odometry motion prior: the body motion between two times is the
// increment of the odometry poses interpolated at those times (linear in
// position, slerp in rotation). Its sigma grows with the increment:
// sigma_p = max(min, k_p * distance), sigma_theta = max(min, k_r * angle +
// k_rm * distance). Times not bracketed by readings at most
// max_odometry_gap_s apart give no prediction; an interval starting before
// the first reading starts at it. Readings not after the previous one (or
// not finite) are skipped and counted.
class WheelOdometryPrior final : public MotionPrior {
 public:
  explicit WheelOdometryPrior(const MotionPriorOptions& options);
  void AddOdometry(const OdometrySample& sample) override;
  bool ReadyFor(double time_s) const override;
  MotionPrediction Predict(double t0, double t1) const override;
  void Observe(double /*time_s*/, const Eigen::Isometry3d& /*T_world_body*/) override {}
  std::size_t rejected() const { return rejected_; }

 private:
  // The odometry pose at time_s; false when time_s is not bracketed.
  bool Interpolate(double time_s, Eigen::Isometry3d* T_odom_body) const;

  MotionPriorOptions options_;
  std::deque<OdometrySample> samples_;  // time order, the last ~30 s
  std::size_t rejected_ = 0;
};

}  // namespace unimap::estimation
