#include "estimation/ConstantVelocityPrior.hpp"

#include "estimation/So3.hpp"

namespace unimap::estimation {

ConstantVelocityPrior::ConstantVelocityPrior(const MotionPriorOptions& options) : options_(options) {}

void ConstantVelocityPrior::Observe(double time_s, const Eigen::Isometry3d& T_world_body) {
  if (observed_ > 0) {
    const double dt = time_s - last_time_s_;
    if (!(dt > 0.0)) return;  // not after the last pose: keep the old velocity
    // Body-frame twist between the two poses (first order: translation and
    // rotation separately), v = R_a^T (p_b - p_a) / dt, w = Log(R_a^T R_b) / dt.
    const Eigen::Isometry3d T_last_now = T_world_last_.inverse() * T_world_body;
    velocity_body_m_s_ = T_last_now.translation() / dt;
    rate_body_rad_s_ = LogQ(Eigen::Quaterniond(T_last_now.linear())) / dt;
  }
  observed_ = std::min(observed_ + 1, 2);
  last_time_s_ = time_s;
  T_world_last_ = T_world_body;
}

MotionPrediction ConstantVelocityPrior::Predict(double t0, double t1) const {
  MotionPrediction out;
  const double dt = t1 - t0;
  if (!(dt >= 0.0)) {
    out.reason = "constant-velocity prior: t1 before t0";
    return out;
  }
  out.ok = true;
  out.T_prev_next.linear() = ExpQ(rate_body_rad_s_ * dt).toRotationMatrix();
  out.T_prev_next.translation() = velocity_body_m_s_ * dt;
  out.covariance = UnmodeledMotionCovariance(options_, dt);
  if (observed_ < 2) {  // no velocity yet: anything up to the fastest expected motion
    const double sigma_p = options_.max_speed_m_s * dt;
    const double sigma_r = options_.max_rate_rad_s * dt;
    out.covariance.diagonal() << Eigen::Vector3d::Constant(sigma_p * sigma_p),
        Eigen::Vector3d::Constant(sigma_r * sigma_r);
  }
  return out;
}

}  // namespace unimap::estimation
