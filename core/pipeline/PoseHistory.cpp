#include "pipeline/PoseHistory.hpp"

#include <algorithm>
#include <cassert>

namespace unimap::pipeline {

void PoseHistory::Add(double time_s, const Eigen::Isometry3d& T_world_body) {
  const Entry entry{time_s, T_world_body.translation(), Eigen::Quaterniond(T_world_body.linear())};
  if (!poses_.empty() && time_s <= poses_.back().time_s) {
    if (time_s == poses_.back().time_s) poses_.back() = entry;
    return;
  }
  poses_.push_back(entry);
  // Keep the pose at or before (time_s - keep_s) so that span is still bracketed.
  while (poses_.size() > 2 && poses_[1].time_s <= time_s - keep_s_) poses_.pop_front();
}

Eigen::Isometry3d PoseHistory::At(double time_s) const {
  assert(!poses_.empty());
  const auto make = [](const Eigen::Vector3d& p, const Eigen::Quaterniond& q) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = q.normalized().toRotationMatrix();
    T.translation() = p;
    return T;
  };
  if (time_s <= poses_.front().time_s) return make(poses_.front().p, poses_.front().q);
  if (time_s >= poses_.back().time_s) return make(poses_.back().p, poses_.back().q);
  const auto it =
      std::lower_bound(poses_.begin(), poses_.end(), time_s, [](const Entry& e, double t) { return e.time_s < t; });
  const Entry& b = *it;
  const Entry& a = *(it - 1);
  const double alpha = (time_s - a.time_s) / (b.time_s - a.time_s);
  return make(a.p + alpha * (b.p - a.p), a.q.slerp(alpha, b.q));
}

}  // namespace unimap::pipeline
