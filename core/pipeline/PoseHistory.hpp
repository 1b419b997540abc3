#pragma once
#include <deque>

#include <Eigen/Geometry>

namespace unimap::pipeline {

// Recent body poses T_world_body(t) from the filter, for deskewing: linear
// interpolation of position and slerp of rotation between stored poses.
class PoseHistory {
 public:
  explicit PoseHistory(double keep_s = 1.0) : keep_s_(keep_s) {}

  // Appends a pose (time after the last; an equal time replaces it); drops
  // poses older than keep_s before it.
  void Add(double time_s, const Eigen::Isometry3d& T_world_body);
  // Forgets everything (after a filter correction).
  void Clear() { poses_.clear(); }
  bool empty() const { return poses_.empty(); }
  double latest_time_s() const { return poses_.back().time_s; }

  // Pose at time_s: interpolated inside the stored span, the nearest end
  // outside it. Requires !empty().
  Eigen::Isometry3d At(double time_s) const;

 private:
  struct Entry {
    double time_s;
    Eigen::Vector3d p;
    Eigen::Quaterniond q;
  };
  double keep_s_;
  std::deque<Entry> poses_;
};

}  // namespace unimap::pipeline
