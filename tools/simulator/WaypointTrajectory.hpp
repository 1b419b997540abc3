#pragma once
#include <vector>

#include <Eigen/Geometry>

#include "Trajectory.hpp"

namespace unimap::sim {

// One stop of a waypoint trajectory.
struct Waypoint {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();  // body origin in the world frame
  double yaw_rad = 0.0;  // heading on arrival; interpolated as written (no wrapping), so 0 -> 6 rad turns 6 rad
  double dwell_s = 0.0;  // time held at rest here after arriving (>= 0)
};

// A small smooth roll/pitch oscillation that excites the IMU (a hovering
// drone or a carried sensor never holds perfectly level):
//   roll(t) = A_r e(t) sin(2 pi t / P_r),  pitch(t) = A_p e(t) sin(2 pi t / P_p + pi/3),
// with e(t) the minimum-jerk ramp from 0 at the end of the static start to 1
// ramp_s later, so the static start stays level and everything stays smooth.
struct Wobble {
  double roll_amplitude_rad = 0.0;   // A_r (>= 0)
  double pitch_amplitude_rad = 0.0;  // A_p (>= 0)
  double roll_period_s = 7.0;        // P_r (> 0)
  double pitch_period_s = 11.0;      // P_p (> 0)
  double ramp_s = 2.0;               // fade-in after the static start (> 0)
};

// Limits that set each segment's duration, and the start.
struct WaypointTrajectoryOptions {
  double max_speed_m_s = 1.0;          // peak speed of any segment (> 0)
  double max_acceleration_m_s2 = 1.0;  // peak acceleration of any segment (> 0)
  double max_yaw_rate_rad_s = 0.5;     // peak yaw rate of any segment (> 0)
  double static_start_s = 0.0;         // level rest at waypoint 0 before anything (>= 0)
  Wobble wobble;                       // roll/pitch excitation after the static start
};

// A body trajectory through waypoints. Each segment is a straight line
// travelled with the minimum-jerk profile from rest to rest, the yaw turning
// with the same profile:
//   p(t) = p_i + (p_{i+1} - p_i) s(u),  yaw(t) = yaw_i + (yaw_{i+1} - yaw_i) s(u),  u = (t - t_i) / T_i,
// so velocity and acceleration are continuous everywhere (zero at the joins
// and during dwells). T_i is the shortest duration keeping the peaks within
// the limits: T = max(1.875 L / v_max, sqrt(5.774 L / a_max), 1.875 |dyaw| / yaw_rate_max).
// Attitude R = Rz(yaw) Ry(pitch) Rx(roll) with roll/pitch from the Wobble.
// Time starts at 0 at waypoint 0.
class WaypointTrajectory final : public Trajectory {
 public:
  // Throws std::invalid_argument for fewer than one waypoint, a non-finite
  // value, a negative dwell or a non-positive limit.
  WaypointTrajectory(std::vector<Waypoint> waypoints, WaypointTrajectoryOptions options);

  double start_time_s() const override { return 0.0; }
  double end_time_s() const override;
  // State at time_s, clamped into [start_time_s, end_time_s].
  KinematicState At(double time_s) const override;

  // Distance travelled by the body origin from 0 to time_s.
  double PathLength(double time_s) const;
  // Highest speed reached from 0 to time_s.
  double MaxSpeed(double time_s) const;
  // Time at which the body arrives at waypoint i (before its dwell).
  double ArrivalTime(std::size_t i) const;

  const std::vector<Waypoint>& waypoints() const { return waypoints_; }
  const WaypointTrajectoryOptions& options() const { return options_; }

 private:
  // A stretch of time: a move between two waypoints or a hold at one.
  struct Phase {
    double t0_s = 0.0;                      // start time
    double duration_s = 0.0;                // > 0
    Eigen::Vector3d p0_m, p1_m;             // start and end position (equal for a hold)
    double yaw0_rad = 0.0, yaw1_rad = 0.0;  // start and end yaw (equal for a hold)
    double length_m = 0.0;                  // |p1 - p0|
    double path_before_m = 0.0;             // distance travelled before this phase
  };
  // Index of the phase containing time_s (already clamped).
  std::size_t PhaseAt(double time_s) const;
  // Wobble roll, pitch and their rates at time_s.
  void WobbleAt(double time_s, double* roll, double* pitch, double* roll_rate, double* pitch_rate) const;

  std::vector<Waypoint> waypoints_;
  WaypointTrajectoryOptions options_;
  std::vector<Phase> phases_;           // in time order, contiguous
  std::vector<double> phase_starts_s_;  // phases_[i].t0_s, for the search
  std::vector<double> arrival_s_;       // per waypoint
};

}  // namespace unimap::sim
