#pragma once
#include <vector>

#include "unimap/Point.hpp"

namespace unimap {

// One scan as the LiDAR delivered it: a 2D line (points in the scanner
// plane) or a 3D sweep, points in the LiDAR frame.
struct RawScan {
  double start_time_s = 0.0;   // time of the first firing
  double end_time_s = 0.0;     // time of the last firing, >= start_time_s
  bool has_point_time = true;  // false: the plugin derives per-point time (e.g. firing order)
  std::vector<Point> points;   // LiDAR frame
};

}  // namespace unimap
