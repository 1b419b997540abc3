#pragma once
#include <functional>
#include <limits>

#include <Eigen/Geometry>

#include "unimap/BodyScan.hpp"
#include "unimap/Export.hpp"
#include "unimap/RawScan.hpp"

namespace unimap {

// Body pose in a fixed world frame at a time, T_world_body(t); supplied by
// the core (filter prediction, ground truth, ...).
using MotionQuery = std::function<Eigen::Isometry3d(double time_s)>;
// LiDAR pose in the body frame at a time, T_body_lidar(t); supplied by the
// payload's sensor model (fixed extrinsic, or motor angle at t).
using MountQuery = std::function<Eigen::Isometry3d(double time_s)>;

// Range limits of the scanner; returns outside are dropped and counted.
struct RangeLimits {
  double min_range_m = 0.0;                                      // inclusive
  double max_range_m = std::numeric_limits<double>::infinity();  // inclusive
};

// Throws InputError for an empty scan, end_time_s < start_time_s (time
// going backwards), a non-finite coordinate or time, or a point time
// outside [start_time_s, end_time_s]; the message names the point index.
UNIMAP_SDK_API void ValidateRawScan(const RawScan& scan);

// Spacing of the times at which DeskewScan evaluates the queries exactly (s).
inline constexpr double kDeskewKnotSpacingS = 0.0005;

// How far DeskewScan's blend between knots may move a point from the exact
// transform (m), for a point range_m from the LiDAR, the LiDAR origin
// lever_arm_m from the body's and mount's rotation axes, body and mount
// angular rates (rad/s), angular acceleration (rad/s^2) and linear
// acceleration (m/s^2) over the scan; with h = kDeskewKnotSpacingS and
// w = body + mount rate:
//   h^2 / 8 (range (w_body w_mount + alpha) + lever w^2 + accel)
//   + range (w h)^3 / 250 (the quaternion blend) + 1e-9 (rounding).
// The curvature of the motion between knots is what the blend misses.
inline double DeskewBlendBoundM(double range_m, double lever_arm_m, double body_rate_rad_s, double mount_rate_rad_s,
                                double angular_accel_rad_s2 = 0.0, double linear_accel_m_s2 = 0.0) {
  const double h = kDeskewKnotSpacingS;
  const double w = body_rate_rad_s + mount_rate_rad_s;
  return h * h / 8.0 *
             (range_m * (body_rate_rad_s * mount_rate_rad_s + angular_accel_rad_s2) + lever_arm_m * w * w +
              linear_accel_m_s2) +
         range_m * (w * h) * (w * h) * (w * h) / 250.0 + 1e-9;
}

// Rigid-body deskew: every point into the body frame at the scan's end time,
//   p_body(t_ref) = T_world_body(t_ref)^-1 * T_world_body(t_i) * T_body_lidar(t_i) * p_lidar(t_i).
// The transform is evaluated exactly at knots kDeskewKnotSpacingS apart from
// the scan's start (and at its end and at any point time outside the
// window) and blended between them (translation linearly, rotation by the
// normalised quaternion blend): the queries are called about twice per
// knot, not per point. Points move from the exact transform by at most
// DeskewBlendBoundM (1.25 um at 10 m with 2 rad/s body and mount rates;
// docs/design.md 1.1). Validates first (ValidateRawScan); errors from the
// queries propagate.
UNIMAP_SDK_API BodyScan DeskewScan(const RawScan& scan, const MountQuery& T_body_lidar_at,
                                   const MotionQuery& T_world_body_at, const RangeLimits& limits);

}  // namespace unimap
