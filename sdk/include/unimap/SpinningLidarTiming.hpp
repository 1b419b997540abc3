#pragma once
#include "unimap/Export.hpp"
#include "unimap/RawScan.hpp"

namespace unimap {

// Firing order of a spinning multi-beam LiDAR (Velodyne class): the head
// turns at a constant rate, so a return's azimuth tells when it fired.
struct UNIMAP_SDK_API SpinningLidarTiming {
  double spin_rate_hz = 10.0;  // head revolutions per second
  bool clockwise = true;       // seen from above (+z); Velodyne heads turn clockwise

  // Sets every point's time from its azimuth relative to the first point:
  //   t_i = start_time_s + wrap_[0,2pi)(s * (az_i - az_0)) / (2 pi spin_rate_hz),
  // s = -1 for clockwise (a swept angle within 1e-5 rad of 2 pi counts as 0:
  // rounding between the rings of one firing); sets end_time_s to the latest time and
  // has_point_time. Throws InputError for an empty scan.
  void AssignPointTimes(RawScan* scan) const;
};

}  // namespace unimap
