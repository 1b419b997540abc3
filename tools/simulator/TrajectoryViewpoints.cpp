#include "TrajectoryViewpoints.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace unimap::sim {

std::vector<Eigen::Vector3d> TrajectoryViewpoints(const Trajectory& trajectory, double end_time_s,
                                                  const ViewpointOptions& options) {
  if (!(options.spacing_m > 0.0 && options.time_step_s > 0.0 && options.dwell_speed_m_s > 0.0 &&
        options.min_separation_m >= 0.0 && std::isfinite(options.spacing_m) && std::isfinite(options.time_step_s) &&
        std::isfinite(options.min_separation_m))) {
    throw std::invalid_argument(
        "TrajectoryViewpoints: spacing_m, time_step_s and dwell_speed_m_s must be "
        "finite and > 0, min_separation_m finite and >= 0");
  }
  if (std::isnan(end_time_s)) throw std::invalid_argument("TrajectoryViewpoints: end_time_s is NaN");
  const double t0 = trajectory.start_time_s();
  const double t1 = std::clamp(end_time_s, t0, trajectory.end_time_s());

  std::vector<Eigen::Vector3d> viewpoints;
  KinematicState state = trajectory.At(t0);
  viewpoints.push_back(state.position_m);
  Eigen::Vector3d previous = state.position_m;  // position at the previous step
  double traveled = 0.0;                        // since the last travel viewpoint
  bool moving = state.velocity_m_s.norm() >= options.dwell_speed_m_s;
  auto add_if_apart = [&](const Eigen::Vector3d& p) {
    if ((p - viewpoints.back()).norm() > options.min_separation_m) viewpoints.push_back(p);
  };
  const auto steps = static_cast<long>(std::ceil((t1 - t0) / options.time_step_s));
  for (long k = 1; k <= steps; ++k) {
    const double t = std::min(t1, t0 + static_cast<double>(k) * options.time_step_s);
    state = trajectory.At(t);
    traveled += (state.position_m - previous).norm();
    previous = state.position_m;
    if (traveled >= options.spacing_m) {
      viewpoints.push_back(state.position_m);
      traveled = 0.0;
    }
    const bool now_moving = state.velocity_m_s.norm() >= options.dwell_speed_m_s;
    if (moving && !now_moving) add_if_apart(state.position_m);  // a dwell begins
    moving = now_moving;
  }
  add_if_apart(previous);
  return viewpoints;
}

}  // namespace unimap::sim
