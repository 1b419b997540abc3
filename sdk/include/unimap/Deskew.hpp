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

// Rigid-body deskew: every point into the body frame at the scan's end time,
//   p_body(t_ref) = T_world_body(t_ref)^-1 * T_world_body(t_i) * T_body_lidar(t_i) * p_lidar(t_i).
// Validates first (ValidateRawScan); errors from the queries propagate.
UNIMAP_SDK_API BodyScan DeskewScan(const RawScan& scan, const MountQuery& T_body_lidar_at,
                                   const MotionQuery& T_world_body_at, const RangeLimits& limits);

}  // namespace unimap
