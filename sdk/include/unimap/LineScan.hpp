#pragma once
#include <cstddef>
#include <vector>

#include "unimap/Export.hpp"
#include "unimap/RawScan.hpp"

namespace unimap {

// A 2D laser line as scanners report it (LaserScan / CARMEN FLASER): beam i
// points at angle_min_rad + i * angle_increment_rad in the scanner's x-y
// plane and fires at start_time_s + i * time_increment_s.
struct LineScan {
  double start_time_s = 0.0;         // time of beam 0
  double angle_min_rad = 0.0;        // direction of beam 0, counter-clockwise from +x
  double angle_increment_rad = 0.0;  // angle between consecutive beams
  double time_increment_s = 0.0;     // time between consecutive beams
  double range_min_m = 0.0;          // shorter returns are invalid
  double range_max_m = 0.0;          // longer returns are invalid
  std::vector<float> ranges_m;       // one per beam; NaN/inf = no return
  std::vector<float> intensities;    // empty, or one per beam
};

// A LineScan turned into points, with what was dropped.
struct LineScanConversion {
  RawScan scan;             // points in the scanner plane (z = 0), per-beam time
  std::size_t dropped = 0;  // beams with no return or outside [range_min_m, range_max_m]
};

// Converts beams to points in the scanner frame; start/end time span every
// beam (also the dropped ones). Throws InputError for a malformed line
// (no beams, non-finite header fields, intensities of another length).
UNIMAP_SDK_API LineScanConversion LineScanToRawScan(const LineScan& line);

}  // namespace unimap
