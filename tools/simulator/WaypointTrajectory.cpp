#include "WaypointTrajectory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "MinimumJerkProfile.hpp"

namespace unimap::sim {
namespace {

using Profile = MinimumJerkProfile;

void Require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("waypoint trajectory: " + what);
}

// Shortest duration whose minimum-jerk peaks respect the limits.
double SegmentDuration(double length_m, double yaw_change_rad, const WaypointTrajectoryOptions& o) {
  const double by_speed = Profile::kPeakVelocity * length_m / o.max_speed_m_s;
  const double by_accel = std::sqrt(Profile::kPeakAcceleration * length_m / o.max_acceleration_m_s2);
  const double by_yaw = Profile::kPeakVelocity * std::abs(yaw_change_rad) / o.max_yaw_rate_rad_s;
  return std::max({by_speed, by_accel, by_yaw});
}

// q = Rz(yaw) Ry(pitch) Rx(roll) from half angles.
Eigen::Quaterniond FromYawPitchRoll(double yaw, double pitch, double roll) {
  const Eigen::Quaterniond qz(std::cos(0.5 * yaw), 0.0, 0.0, std::sin(0.5 * yaw));
  const Eigen::Quaterniond qy(std::cos(0.5 * pitch), 0.0, std::sin(0.5 * pitch), 0.0);
  const Eigen::Quaterniond qx(std::cos(0.5 * roll), std::sin(0.5 * roll), 0.0, 0.0);
  return qz * qy * qx;
}

}  // namespace

WaypointTrajectory::WaypointTrajectory(std::vector<Waypoint> waypoints, WaypointTrajectoryOptions options)
    : waypoints_(std::move(waypoints)), options_(options) {
  const auto& o = options_;
  const auto& w = o.wobble;
  Require(!waypoints_.empty(), "needs at least one waypoint");
  Require(std::isfinite(o.max_speed_m_s) && o.max_speed_m_s > 0.0, "max speed must be positive");
  Require(std::isfinite(o.max_acceleration_m_s2) && o.max_acceleration_m_s2 > 0.0, "max acceleration must be positive");
  Require(std::isfinite(o.max_yaw_rate_rad_s) && o.max_yaw_rate_rad_s > 0.0, "max yaw rate must be positive");
  Require(std::isfinite(o.static_start_s) && o.static_start_s >= 0.0, "static start must be >= 0");
  Require(std::isfinite(w.roll_amplitude_rad) && w.roll_amplitude_rad >= 0.0 && std::isfinite(w.pitch_amplitude_rad) &&
              w.pitch_amplitude_rad >= 0.0,
          "wobble amplitudes must be >= 0");
  Require(std::isfinite(w.roll_period_s) && w.roll_period_s > 0.0 && std::isfinite(w.pitch_period_s) &&
              w.pitch_period_s > 0.0 && std::isfinite(w.ramp_s) && w.ramp_s > 0.0,
          "wobble periods and ramp must be positive");
  for (std::size_t i = 0; i < waypoints_.size(); ++i) {
    const Waypoint& p = waypoints_[i];
    Require(p.position_m.allFinite() && std::isfinite(p.yaw_rad) && std::isfinite(p.dwell_s),
            "waypoint " + std::to_string(i) + " has a non-finite value");
    Require(p.dwell_s >= 0.0, "waypoint " + std::to_string(i) + " has a negative dwell");
  }

  double t = 0.0;
  double path = 0.0;
  auto add_hold = [&](const Waypoint& at, double duration_s) {
    if (duration_s <= 0.0) return;
    phases_.push_back({t, duration_s, at.position_m, at.position_m, at.yaw_rad, at.yaw_rad, 0.0, path});
    t += duration_s;
  };
  add_hold(waypoints_[0], o.static_start_s);
  arrival_s_.push_back(t);
  add_hold(waypoints_[0], waypoints_[0].dwell_s);
  for (std::size_t i = 1; i < waypoints_.size(); ++i) {
    const Waypoint& a = waypoints_[i - 1];
    const Waypoint& b = waypoints_[i];
    const double length = (b.position_m - a.position_m).norm();
    const double duration = SegmentDuration(length, b.yaw_rad - a.yaw_rad, o);
    if (duration > 0.0) {
      phases_.push_back({t, duration, a.position_m, b.position_m, a.yaw_rad, b.yaw_rad, length, path});
      t += duration;
      path += length;
    }
    arrival_s_.push_back(t);
    add_hold(b, b.dwell_s);
  }
  for (const Phase& phase : phases_) phase_starts_s_.push_back(phase.t0_s);
}

double WaypointTrajectory::end_time_s() const {
  return phases_.empty() ? 0.0 : phases_.back().t0_s + phases_.back().duration_s;
}

double WaypointTrajectory::ArrivalTime(std::size_t i) const { return arrival_s_.at(i); }

std::size_t WaypointTrajectory::PhaseAt(double time_s) const {
  const auto it = std::upper_bound(phase_starts_s_.begin(), phase_starts_s_.end(), time_s);
  return it == phase_starts_s_.begin() ? 0 : static_cast<std::size_t>(it - phase_starts_s_.begin()) - 1;
}

void WaypointTrajectory::WobbleAt(double time_s, double* roll, double* pitch, double* roll_rate,
                                  double* pitch_rate) const {
  const Wobble& w = options_.wobble;
  // Envelope e(t) and its rate: the minimum-jerk ramp after the static start.
  const double u = (time_s - options_.static_start_s) / w.ramp_s;
  const double e = Profile::Position(u);
  const double e_rate = Profile::Velocity(u) / w.ramp_s;
  const double wr = 2.0 * M_PI / w.roll_period_s;
  const double wp = 2.0 * M_PI / w.pitch_period_s;
  const double phase_p = wp * time_s + M_PI / 3.0;
  *roll = w.roll_amplitude_rad * e * std::sin(wr * time_s);
  *roll_rate = w.roll_amplitude_rad * (e_rate * std::sin(wr * time_s) + e * wr * std::cos(wr * time_s));
  *pitch = w.pitch_amplitude_rad * e * std::sin(phase_p);
  *pitch_rate = w.pitch_amplitude_rad * (e_rate * std::sin(phase_p) + e * wp * std::cos(phase_p));
}

KinematicState WaypointTrajectory::At(double time_s) const {
  KinematicState state;
  const double t = std::clamp(time_s, start_time_s(), end_time_s());
  state.time_s = time_s;
  double yaw = waypoints_[0].yaw_rad;
  double yaw_rate = 0.0;
  state.position_m = waypoints_[0].position_m;
  if (!phases_.empty()) {
    const Phase& ph = phases_[PhaseAt(t)];
    const double u = std::clamp((t - ph.t0_s) / ph.duration_s, 0.0, 1.0);
    const double s = Profile::Position(u);
    const double s_rate = Profile::Velocity(u) / ph.duration_s;
    const double s_accel = Profile::Acceleration(u) / (ph.duration_s * ph.duration_s);
    const Eigen::Vector3d delta = ph.p1_m - ph.p0_m;
    state.position_m = ph.p0_m + delta * s;
    state.velocity_m_s = delta * s_rate;
    state.acceleration_m_s2 = delta * s_accel;
    yaw = ph.yaw0_rad + (ph.yaw1_rad - ph.yaw0_rad) * s;
    yaw_rate = (ph.yaw1_rad - ph.yaw0_rad) * s_rate;
  }
  double roll = 0.0, pitch = 0.0, roll_rate = 0.0, pitch_rate = 0.0;
  WobbleAt(t, &roll, &pitch, &roll_rate, &pitch_rate);
  state.q_world_body = FromYawPitchRoll(yaw, pitch, roll);
  // Body rates of R = Rz(yaw) Ry(pitch) Rx(roll):
  //   omega_body = Rx^T Ry^T (0, 0, yaw') + Rx^T (0, pitch', 0) + (roll', 0, 0).
  const double sr = std::sin(roll), cr = std::cos(roll);
  const double sp = std::sin(pitch), cp = std::cos(pitch);
  state.angular_velocity_body_rad_s = Eigen::Vector3d(roll_rate - yaw_rate * sp, pitch_rate * cr + yaw_rate * cp * sr,
                                                      -pitch_rate * sr + yaw_rate * cp * cr);
  return state;
}

double WaypointTrajectory::PathLength(double time_s) const {
  if (phases_.empty()) return 0.0;
  const double t = std::clamp(time_s, start_time_s(), end_time_s());
  const Phase& ph = phases_[PhaseAt(t)];
  return ph.path_before_m + ph.length_m * Profile::Position((t - ph.t0_s) / ph.duration_s);
}

double WaypointTrajectory::MaxSpeed(double time_s) const {
  double best = 0.0;
  for (const Phase& ph : phases_) {
    if (ph.t0_s >= time_s) break;
    // Speed rises until u = 1/2, so the peak so far is at min(u_end, 1/2).
    const double u = std::min(0.5, (time_s - ph.t0_s) / ph.duration_s);
    best = std::max(best, ph.length_m * Profile::Velocity(u) / ph.duration_s);
  }
  return best;
}

}  // namespace unimap::sim
