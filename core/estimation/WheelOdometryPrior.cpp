#include "estimation/WheelOdometryPrior.hpp"

#include <algorithm>
#include <cmath>

#include "estimation/So3.hpp"

namespace unimap::estimation {
namespace {

constexpr double kKeepS = 30.0;  // readings older than this behind the newest are dropped

}  // namespace

WheelOdometryPrior::WheelOdometryPrior(const MotionPriorOptions& options) : options_(options) {}

void WheelOdometryPrior::AddOdometry(const OdometrySample& sample) {
  if (!std::isfinite(sample.time_s) || !sample.T_odom_body.matrix().allFinite() ||
      (!samples_.empty() && !(sample.time_s > samples_.back().time_s))) {
    ++rejected_;
    return;
  }
  samples_.push_back(sample);
  while (samples_.size() > 2 && samples_.front().time_s < sample.time_s - kKeepS) samples_.pop_front();
}

bool WheelOdometryPrior::ReadyFor(double time_s) const { return !samples_.empty() && samples_.back().time_s >= time_s; }

bool WheelOdometryPrior::Interpolate(double time_s, Eigen::Isometry3d* T_odom_body) const {
  if (samples_.empty() || time_s < samples_.front().time_s || time_s > samples_.back().time_s) return false;
  auto hi = std::lower_bound(samples_.begin(), samples_.end(), time_s,
                             [](const OdometrySample& s, double t) { return s.time_s < t; });
  if (hi->time_s == time_s) {
    *T_odom_body = hi->T_odom_body;
    return true;
  }
  const OdometrySample& b = *hi;
  const OdometrySample& a = *(hi - 1);
  if (b.time_s - a.time_s > options_.max_odometry_gap_s) return false;
  const double f = (time_s - a.time_s) / (b.time_s - a.time_s);
  *T_odom_body = InterpolatePose(a.T_odom_body, b.T_odom_body, f);
  return true;
}

MotionPrediction WheelOdometryPrior::Predict(double t0, double t1) const {
  MotionPrediction out;
  Eigen::Isometry3d T0, T1;
  if (!(t1 >= t0)) {
    out.reason = "wheel-odometry prior: t1 before t0";
    return out;
  }
  // Motion before the first reading is unknown: the increment starts there.
  if (!samples_.empty() && t0 < samples_.front().time_s && t1 >= samples_.front().time_s) t0 = samples_.front().time_s;
  const bool have_t0 = Interpolate(t0, &T0);
  if (!have_t0 || !Interpolate(t1, &T1)) {
    out.reason = "no wheel odometry around " + std::to_string(have_t0 ? t1 : t0) + " s";
    return out;
  }
  out.ok = true;
  out.T_prev_next = T0.inverse() * T1;  // the increment, body frame at t0
  const double distance_m = out.T_prev_next.translation().norm();
  const double angle_rad = LogQ(Eigen::Quaterniond(out.T_prev_next.linear())).norm();
  const double sigma_p = std::max(options_.odometry_min_sigma_m, options_.odometry_sigma_per_m * distance_m);
  const double sigma_r = std::max(options_.odometry_min_sigma_rad, options_.odometry_sigma_rad_per_rad * angle_rad +
                                                                       options_.odometry_sigma_rad_per_m * distance_m);
  out.covariance.diagonal() << Eigen::Vector3d::Constant(sigma_p * sigma_p),
      Eigen::Vector3d::Constant(sigma_r * sigma_r);
  return out;
}

}  // namespace unimap::estimation
