#pragma once
#include <vector>

#include <Eigen/Core>

#include "Trajectory.hpp"

namespace unimap::sim {

// Where along a trajectory to look from when sampling the true map.
struct ViewpointOptions {
  double spacing_m = 0.5;          // a viewpoint every this much travel (> 0)
  double time_step_s = 0.05;       // the trajectory is scanned at this step (> 0)
  double dwell_speed_m_s = 1e-3;   // below this speed the body is dwelling (> 0)
  double min_separation_m = 0.01;  // a dwell point this close to the previous viewpoint adds none (>= 0)
};

// Body positions (world frame) along the trajectory from its start to
// end_time_s (clamped into the trajectory's span), in time order: the start,
// one whenever the travelled distance since the previous viewpoint reaches
// spacing_m, one where each dwell begins (the speed falling below
// dwell_speed_m_s), and the end, each dwell point and the end skipped when
// within min_separation_m of the previous viewpoint. Throws
// std::invalid_argument for options out of range.
std::vector<Eigen::Vector3d> TrajectoryViewpoints(const Trajectory& trajectory, double end_time_s,
                                                  const ViewpointOptions& options = {});

}  // namespace unimap::sim
