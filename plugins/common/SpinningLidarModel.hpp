#pragma once
#include "unimap/BodyScan.hpp"
#include "unimap/Deskew.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"
#include "unimap/RawScan.hpp"
#include "unimap/SpinningLidarTiming.hpp"

namespace unimap::payload {

// A spinning multi-beam LiDAR (Velodyne VLP-16 class) as the "lidar.*" keys
// describe it. Shared by fixed_3d and rotating_3d, which differ only in how
// the LiDAR is mounted (the MountQuery passed to Deskew). The default values
// describe a Velodyne VLP-16 (16 rings over -15..+15 deg, clockwise at 10 Hz,
// returns 0.4..100 m), the default of both plugins.
struct SpinningLidarModel {
  // When the points of a sweep delivered without per-point time fired.
  enum class Timing {
    kAzimuth,  // a spinning head: from each point's azimuth (SpinningLidarTiming)
    kNone,     // a snapshot: every point at the sweep's start time (clouds already
               // deskewed, e.g. KITTI's, or a non-spinning sensor without point times)
  };
  int rings = 16;                          // beams stacked vertically
  double vertical_fov_min_deg = -15.0;     // elevation of the lowest beam (deg)
  double vertical_fov_max_deg = 15.0;      // elevation of the highest beam (deg)
  SpinningLidarTiming timing;              // head spin rate and direction (firing order)
  Timing point_timing = Timing::kAzimuth;  // "lidar.timing": points without their own time
  RangeLimits limits{0.4, 100.0};          // valid returns (m)

  // Adds "lidar.rings", "lidar.vertical_fov_deg", "lidar.spin_rate_hz",
  // "lidar.clockwise", "lidar.timing", "lidar.min_range_m",
  // "lidar.max_range_m" with this object's values as defaults.
  void AddTo(ParameterSet* set) const;
  // Reads those keys; throws ConfigError (vertical FOV min >= max, range
  // limits out of order, wrong types).
  static SpinningLidarModel FromMap(const ParameterMap& map);

  // Rigid-body deskew of one sweep (DeskewScan with these range limits).
  // Points with their own time (scan.has_point_time) keep it. Otherwise,
  // with kAzimuth, every point's firing time is first derived from its
  // azimuth (SpinningLidarTiming::AssignPointTimes: the first point fires at
  // start_time_s, end_time_s becomes the last firing); with kNone every
  // point is taken at start_time_s, which becomes the reference time.
  // Throws InputError on bad input; errors of the queries propagate.
  BodyScan Deskew(const RawScan& scan, const MountQuery& T_body_lidar_at, const MotionQuery& T_world_body_at) const;
};

}  // namespace unimap::payload
