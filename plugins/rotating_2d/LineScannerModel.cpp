#include "LineScannerModel.hpp"

#include <cmath>
#include <string>

#include "../common/RangeLimitParameters.hpp"
#include "unimap/Errors.hpp"

namespace unimap::payload {
namespace {

constexpr const char* kScanRate = "lidar.scan_rate_hz";
constexpr const char* kFov = "lidar.fov_deg";
constexpr const char* kBeams = "lidar.beams";
constexpr double kDegToRad = M_PI / 180.0;

}  // namespace

void LineScannerModel::AddTo(ParameterSet* set) const {
  set->Add({kScanRate, "", "lines per second (mirror revolutions per second) (Hz)", scan_rate_hz, 0.1, 1000.0, {}});
  set->Add(
      {kFov, "", "angle from the first to the last beam, centred on the scanner's +x (deg)", fov_deg, 1.0, 360.0, {}});
  set->Add({kBeams, "", "beams per line, first and last included (count)", std::int64_t{beams}, 2, 1000000, {}});
  RangeLimitParameters::AddTo(limits, set);
}

LineScannerModel LineScannerModel::FromMap(const ParameterMap& map) {
  LineScannerModel model;
  model.scan_rate_hz = map.GetDouble(kScanRate);
  if (!(model.scan_rate_hz > 0.0)) throw ConfigError("", 0, kScanRate, "must be positive");
  model.fov_deg = map.GetDouble(kFov);
  if (!(model.fov_deg > 0.0 && model.fov_deg <= 360.0)) {
    throw ConfigError("", 0, kFov, "must be in (0, 360]");
  }
  const std::int64_t beams = map.GetInt(kBeams);
  if (beams < 2 || beams > 1000000) throw ConfigError("", 0, kBeams, "must be in [2, 1000000]");
  model.beams = static_cast<int>(beams);
  model.limits = RangeLimitParameters::FromMap(map);
  return model;
}

double LineScannerModel::BeamInterval() const {
  return (fov_deg / static_cast<double>(beams - 1)) / (360.0 * scan_rate_hz);
}

void LineScannerModel::AssignPointTimes(RawScan* scan) const {
  if (scan->points.empty()) throw InputError("empty scan (no points): cannot derive beam times");
  if (!std::isfinite(scan->start_time_s)) throw InputError("scan start time is not finite");
  const double angle_min_rad = -0.5 * fov_deg * kDegToRad;
  const double step_rad = fov_deg * kDegToRad / static_cast<double>(beams - 1);
  const double interval_s = BeamInterval();
  const double last_beam = static_cast<double>(beams - 1);
  for (std::size_t i = 0; i < scan->points.size(); ++i) {
    Point& point = scan->points[i];
    if (!point.position_m.allFinite()) {
      throw InputError("point " + std::to_string(i) + ": non-finite coordinate");
    }
    const double azimuth_rad = std::atan2(point.position_m.y(), point.position_m.x());
    const double beam = std::round((azimuth_rad - angle_min_rad) / step_rad);
    if (!(beam >= 0.0 && beam <= last_beam)) {
      throw InputError("point " + std::to_string(i) + ": azimuth " + std::to_string(azimuth_rad / kDegToRad) +
                       " deg is outside the scanner's field of view");
    }
    point.time_s = scan->start_time_s + beam * interval_s;
  }
  scan->end_time_s = scan->start_time_s + last_beam * interval_s;
  scan->has_point_time = true;
}

BodyScan LineScannerModel::Deskew(const RawScan& scan, const MountQuery& T_body_lidar_at,
                                  const MotionQuery& T_world_body_at) const {
  if (scan.has_point_time) return DeskewScan(scan, T_body_lidar_at, T_world_body_at, limits);
  RawScan timed = scan;
  AssignPointTimes(&timed);
  return DeskewScan(timed, T_body_lidar_at, T_world_body_at, limits);
}

}  // namespace unimap::payload
