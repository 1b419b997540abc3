#include "unimap/SpinningLidarTiming.hpp"

#include <cmath>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {
// Far below a VLP-16's 3.5e-3 rad between firings.
constexpr double kRoundingWrapRad = 1e-5;
}  // namespace

void SpinningLidarTiming::AssignPointTimes(RawScan* scan) const {
  if (scan->points.empty()) throw InputError("scan has no points: cannot derive firing times");
  if (!(spin_rate_hz > 0.0)) throw InputError("spin rate must be positive to derive firing times");
  const double direction = clockwise ? -1.0 : 1.0;
  const double period_s = 1.0 / spin_rate_hz;
  const Eigen::Vector3d& first = scan->points.front().position_m;
  const double azimuth0 = std::atan2(first.y(), first.x());
  double latest = scan->start_time_s;
  for (Point& point : scan->points) {
    const double azimuth = std::atan2(point.position_m.y(), point.position_m.x());
    // Angle the head turned since the first firing, in [0, 2pi).
    double swept = std::fmod(direction * (azimuth - azimuth0), 2.0 * M_PI);
    if (swept < 0.0) swept += 2.0 * M_PI;
    // Returns of one firing share an azimuth up to rounding (1e-7 rad for
    // float data): a ring computed just behind the first one is not a whole
    // revolution later.
    if (swept > 2.0 * M_PI - kRoundingWrapRad) swept = 0.0;
    point.time_s = scan->start_time_s + period_s * swept / (2.0 * M_PI);
    latest = std::max(latest, point.time_s);
  }
  scan->end_time_s = latest;
  scan->has_point_time = true;
}

}  // namespace unimap
