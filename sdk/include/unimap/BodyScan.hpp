#pragma once
#include <cstddef>
#include <vector>

#include "unimap/Point.hpp"

namespace unimap {

// A deskewed scan: every point in the body (IMU) frame at reference_time_s.
struct BodyScan {
  double reference_time_s = 0.0;         // the raw scan's end_time_s
  std::vector<Point> points;             // body frame at reference_time_s; time_s is the firing time
  std::size_t dropped_out_of_range = 0;  // returns outside the payload's range limits
};

}  // namespace unimap
