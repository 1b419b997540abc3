#pragma once
#include <vector>

#include <Eigen/Geometry>

#include "unimap/Deskew.hpp"

namespace unimap::sim {

// The LiDAR pose in the world over one scan,
//   T_world_lidar(t) = T_world_body(t) * T_body_lidar(t),
// from the trajectory (MotionQuery) and the payload's own sensor model
// (MountQuery, e.g. plugin->BodyFromLidarAt(encoder, t)). Evaluating both per
// beam costs more than casting the ray, so exact poses are taken at knots
// spaced at most knot_interval_s apart and interpolated in between
// (translation linearly, rotation by normalised quaternion lerp). With the
// default 1 ms knots a 30 rpm motor turns 3.1 mrad between knots; the
// interpolation error is below 1e-6 m and 1e-6 rad for the rigs simulated.
// knot_interval_s = 0 evaluates both queries at every beam (exact).
class LidarPoseTrack {
 public:
  // Throws std::invalid_argument for a negative or non-finite knot interval.
  LidarPoseTrack(MotionQuery T_world_body_at, MountQuery T_body_lidar_at, double knot_interval_s = 1e-3);

  // Takes the knots covering [start_time_s, end_time_s] (both included);
  // errors of the queries (e.g. InputError outside encoder coverage) propagate.
  void Prepare(double start_time_s, double end_time_s);
  // T_world_lidar at a time in the prepared span: rotation and origin.
  void At(double time_s, Eigen::Quaterniond* q_world_lidar, Eigen::Vector3d* p_world_lidar) const;
  // Exact T_world_lidar at any time the queries cover.
  Eigen::Isometry3d Exact(double time_s) const;

 private:
  MotionQuery T_world_body_at_;
  MountQuery T_body_lidar_at_;
  double knot_interval_s_;
  double start_s_ = 0.0;               // time of knot 0
  double step_s_ = 0.0;                // time between knots (0: single knot)
  std::vector<Eigen::Quaterniond> q_;  // q_world_lidar per knot, consecutive ones in one hemisphere
  std::vector<Eigen::Vector3d> p_;     // p_world_lidar per knot
};

}  // namespace unimap::sim
