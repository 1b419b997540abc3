#include "SpinningLidarModel.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "RangeLimitParameters.hpp"
#include "unimap/Errors.hpp"  // ConfigError

namespace unimap::payload {
namespace {
constexpr const char* kRings = "lidar.rings";
constexpr const char* kVerticalFov = "lidar.vertical_fov_deg";
constexpr const char* kSpinRate = "lidar.spin_rate_hz";
constexpr const char* kClockwise = "lidar.clockwise";
constexpr const char* kTiming = "lidar.timing";
constexpr const char* kTimingAzimuth = "azimuth";
constexpr const char* kTimingNone = "none";

}  // namespace

void SpinningLidarModel::AddTo(ParameterSet* set) const {
  set->Add({kRings, "", "number of beams (rings) stacked vertically (count)", std::int64_t{rings}, 1, 256, {}});
  set->Add({kVerticalFov,
            "",
            "elevation of the lowest and the highest beam [min, max] (deg)",
            std::vector<double>{vertical_fov_min_deg, vertical_fov_max_deg},
            -90.0,
            90.0,
            {}});
  set->Add({kSpinRate,
            "",
            "head revolutions per second; a sweep is one revolution and sets the firing time "
            "of points delivered without per-point time (Hz)",
            timing.spin_rate_hz,
            0.1,
            100.0,
            {}});
  set->Add({kClockwise,
            "",
            "head turns clockwise seen from +z (Velodyne heads do)",
            timing.clockwise,
            -std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity(),
            {}});
  set->Add({kTiming,
            "",
            "firing time of points delivered without their own time: azimuth (a spinning head, "
            "from each point's azimuth) or none (a snapshot at the sweep's start time: clouds "
            "already deskewed, non-spinning sensors)",
            std::string(point_timing == Timing::kAzimuth ? kTimingAzimuth : kTimingNone),
            -std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity(),
            {kTimingAzimuth, kTimingNone}});
  RangeLimitParameters::AddTo(limits, set);
}

SpinningLidarModel SpinningLidarModel::FromMap(const ParameterMap& map) {
  SpinningLidarModel model;
  const std::int64_t rings = map.GetInt(kRings);
  if (rings < 1 || rings > 256) throw ConfigError("", 0, kRings, "must be in [1, 256]");
  model.rings = static_cast<int>(rings);
  const std::vector<double> fov = map.GetVector(kVerticalFov, 2);
  if (!(fov[0] >= -90.0 && fov[0] < fov[1] && fov[1] <= 90.0)) {
    throw ConfigError("", 0, kVerticalFov, "must be [min, max] with -90 <= min < max <= 90");
  }
  model.vertical_fov_min_deg = fov[0];
  model.vertical_fov_max_deg = fov[1];
  model.timing.spin_rate_hz = map.GetDouble(kSpinRate);
  if (!(model.timing.spin_rate_hz > 0.0)) throw ConfigError("", 0, kSpinRate, "must be positive");
  model.timing.clockwise = map.GetBool(kClockwise);
  const std::string point_timing = map.GetString(kTiming);
  if (point_timing == kTimingAzimuth) {
    model.point_timing = Timing::kAzimuth;
  } else if (point_timing == kTimingNone) {
    model.point_timing = Timing::kNone;
  } else {
    throw ConfigError("", 0, kTiming, "must be 'azimuth' or 'none', not '" + point_timing + "'");
  }
  model.limits = RangeLimitParameters::FromMap(map);
  return model;
}

BodyScan SpinningLidarModel::Deskew(const RawScan& scan, const MountQuery& T_body_lidar_at,
                                    const MotionQuery& T_world_body_at) const {
  if (scan.has_point_time) return DeskewScan(scan, T_body_lidar_at, T_world_body_at, limits);
  RawScan timed = scan;
  if (point_timing == Timing::kNone) {
    for (Point& p : timed.points) p.time_s = timed.start_time_s;
    timed.end_time_s = timed.start_time_s;
    timed.has_point_time = true;
    return DeskewScan(timed, T_body_lidar_at, T_world_body_at, limits);
  }
  timing.AssignPointTimes(&timed);  // throws InputError for an empty scan
  return DeskewScan(timed, T_body_lidar_at, T_world_body_at, limits);
}

}  // namespace unimap::payload
