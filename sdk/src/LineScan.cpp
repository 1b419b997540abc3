#include "unimap/LineScan.hpp"

#include <cmath>

#include "unimap/Errors.hpp"

namespace unimap {

LineScanConversion LineScanToRawScan(const LineScan& line) {
  if (line.ranges_m.empty()) throw InputError("line scan has no beams");
  if (!std::isfinite(line.start_time_s) || !std::isfinite(line.angle_min_rad) ||
      !std::isfinite(line.angle_increment_rad) || !std::isfinite(line.time_increment_s) ||
      line.time_increment_s < 0.0) {
    throw InputError("line scan header has a non-finite field or a negative time increment");
  }
  if (!line.intensities.empty() && line.intensities.size() != line.ranges_m.size()) {
    throw InputError("line scan has " + std::to_string(line.intensities.size()) + " intensities for " +
                     std::to_string(line.ranges_m.size()) + " beams");
  }
  LineScanConversion out;
  out.scan.start_time_s = line.start_time_s;
  out.scan.end_time_s = line.start_time_s + line.time_increment_s * static_cast<double>(line.ranges_m.size() - 1);
  out.scan.has_point_time = true;
  out.scan.points.reserve(line.ranges_m.size());
  for (std::size_t i = 0; i < line.ranges_m.size(); ++i) {
    const double range = line.ranges_m[i];
    if (!std::isfinite(range) || range < line.range_min_m || range > line.range_max_m) {
      ++out.dropped;
      continue;
    }
    const double angle = line.angle_min_rad + line.angle_increment_rad * static_cast<double>(i);
    Point p;
    p.position_m = Eigen::Vector3d(range * std::cos(angle), range * std::sin(angle), 0.0);
    p.time_s = line.start_time_s + line.time_increment_s * static_cast<double>(i);
    p.intensity = line.intensities.empty() ? 0.0f : line.intensities[i];
    out.scan.points.push_back(p);
  }
  return out;
}

}  // namespace unimap
