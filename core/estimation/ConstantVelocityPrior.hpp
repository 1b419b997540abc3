#pragma once
#include "estimation/MotionPrior.hpp"
#include "estimation/MotionPriorOptions.hpp"

namespace unimap::estimation {

// Constant-velocity motion prior: the body keeps the linear and angular
// velocity (body frame) of its last two localised poses. The uncertainty
// grows linearly with the prediction time: sigma_p = velocity_sigma_m_s dt,
// sigma_theta = rate_sigma_rad_s dt. Before two poses are known the velocity
// is unknown: the prediction stands still with sigma_p = max_speed_m_s dt and
// sigma_theta = max_rate_rad_s dt (a sensor may already be moving; the
// localiser then searches wide, pipeline::Reacquirer).
class ConstantVelocityPrior final : public MotionPrior {
 public:
  explicit ConstantVelocityPrior(const MotionPriorOptions& options);
  void AddOdometry(const OdometrySample& /*sample*/) override {}
  bool ReadyFor(double /*time_s*/) const override { return true; }
  MotionPrediction Predict(double t0, double t1) const override;
  void Observe(double time_s, const Eigen::Isometry3d& T_world_body) override;

 private:
  MotionPriorOptions options_;
  int observed_ = 0;          // poses observed (saturates at 2)
  double last_time_s_ = 0.0;  // time of the last observed pose
  Eigen::Isometry3d T_world_last_ = Eigen::Isometry3d::Identity();
  Eigen::Vector3d velocity_body_m_s_ = Eigen::Vector3d::Zero();  // linear velocity, body frame
  Eigen::Vector3d rate_body_rad_s_ = Eigen::Vector3d::Zero();    // angular velocity, body frame
};

}  // namespace unimap::estimation
