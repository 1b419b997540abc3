#pragma once
#include "unimap/BodyScan.hpp"
#include "unimap/Deskew.hpp"
#include "unimap/ParameterMap.hpp"
#include "unimap/ParameterSet.hpp"
#include "unimap/RawScan.hpp"

namespace unimap::payload {

// A 2D laser line scanner (Hokuyo UTM-30LX class) as the "lidar.*" keys
// describe it: a mirror turning counter-clockwise about the scanner's z axis
// at scan_rate_hz fires `beams` beams evenly over `fov_deg`, centred on +x
// (beam 0 at -fov/2, as LaserScan's angle_min). The default values describe
// a UTM-30LX: 40 Hz, 270 deg, 1081 beams (0.25 deg apart), 0.1..30 m.
struct LineScannerModel {
  double scan_rate_hz = 40.0;     // lines (mirror revolutions) per second
  double fov_deg = 270.0;         // angle from the first to the last beam
  int beams = 1081;               // beams per line, first and last included
  RangeLimits limits{0.1, 30.0};  // valid returns (m)

  // Adds "lidar.scan_rate_hz", "lidar.fov_deg", "lidar.beams",
  // "lidar.min_range_m", "lidar.max_range_m" with this object's values as defaults.
  void AddTo(ParameterSet* set) const;
  // Reads those keys; throws ConfigError.
  static LineScannerModel FromMap(const ParameterMap& map);

  // Time between consecutive beams: (fov / (beams - 1)) / (360 deg * scan_rate_hz).
  double BeamInterval() const;
  // Sets each point's firing time from its beam, the beam being the nearest
  // to its azimuth atan2(y, x):
  //   k_i = round((az_i + fov/2) / step),  t_i = start_time_s + k_i * BeamInterval(),
  // sets end_time_s to the last beam's time (start + (beams - 1) * interval,
  // as LineScanToRawScan) and has_point_time. Throws InputError naming the
  // point for a non-finite coordinate or an azimuth outside the FOV (by more
  // than half a beam step), and for an empty scan or a non-finite start time.
  void AssignPointTimes(RawScan* scan) const;
  // Rigid-body deskew of one line (DeskewScan with these range limits),
  // deriving point times first when scan.has_point_time is false.
  BodyScan Deskew(const RawScan& scan, const MountQuery& T_body_lidar_at, const MotionQuery& T_world_body_at) const;
};

}  // namespace unimap::payload
