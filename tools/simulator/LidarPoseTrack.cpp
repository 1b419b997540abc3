#include "LidarPoseTrack.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unimap::sim {

LidarPoseTrack::LidarPoseTrack(MotionQuery T_world_body_at, MountQuery T_body_lidar_at, double knot_interval_s)
    : T_world_body_at_(std::move(T_world_body_at)),
      T_body_lidar_at_(std::move(T_body_lidar_at)),
      knot_interval_s_(knot_interval_s) {
  if (!(std::isfinite(knot_interval_s_) && knot_interval_s_ >= 0.0)) {
    throw std::invalid_argument("pose knot interval must be >= 0");
  }
}

Eigen::Isometry3d LidarPoseTrack::Exact(double time_s) const {
  return T_world_body_at_(time_s) * T_body_lidar_at_(time_s);
}

void LidarPoseTrack::Prepare(double start_time_s, double end_time_s) {
  start_s_ = start_time_s;
  q_.clear();
  p_.clear();
  if (knot_interval_s_ == 0.0) return;
  const double span = std::max(0.0, end_time_s - start_time_s);
  const auto intervals = static_cast<std::size_t>(std::max(1.0, std::ceil(span / knot_interval_s_)));
  step_s_ = span / static_cast<double>(intervals);
  for (std::size_t k = 0; k <= intervals; ++k) {
    const double t = k == intervals ? end_time_s : start_time_s + static_cast<double>(k) * step_s_;
    const Eigen::Isometry3d T_world_lidar = Exact(t);
    Eigen::Quaterniond q(T_world_lidar.rotation());
    if (!q_.empty() && q_.back().dot(q) < 0.0) q.coeffs() = -q.coeffs();
    q_.push_back(q);
    p_.push_back(T_world_lidar.translation());
  }
}

void LidarPoseTrack::At(double time_s, Eigen::Quaterniond* q_world_lidar, Eigen::Vector3d* p_world_lidar) const {
  if (q_.empty()) {
    const Eigen::Isometry3d T = Exact(time_s);
    *q_world_lidar = Eigen::Quaterniond(T.rotation());
    *p_world_lidar = T.translation();
    return;
  }
  if (step_s_ <= 0.0) {
    *q_world_lidar = q_.front();
    *p_world_lidar = p_.front();
    return;
  }
  const double x = (time_s - start_s_) / step_s_;
  const std::size_t last = q_.size() - 2;
  const std::size_t k = std::min(last, static_cast<std::size_t>(std::max(0.0, std::floor(x))));
  const double a = std::clamp(x - static_cast<double>(k), 0.0, 1.0);
  q_world_lidar->coeffs() = (1.0 - a) * q_[k].coeffs() + a * q_[k + 1].coeffs();
  q_world_lidar->normalize();
  *p_world_lidar = (1.0 - a) * p_[k] + a * p_[k + 1];
}

}  // namespace unimap::sim
