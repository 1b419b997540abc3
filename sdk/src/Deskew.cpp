#include "unimap/Deskew.hpp"

#include <cmath>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

std::string PointLabel(std::size_t index) { return "point " + std::to_string(index) + ": "; }

}  // namespace

void ValidateRawScan(const RawScan& scan) {
  if (scan.points.empty()) throw InputError("empty scan (no points)");
  if (!std::isfinite(scan.start_time_s) || !std::isfinite(scan.end_time_s)) {
    throw InputError("scan start or end time is not finite");
  }
  if (scan.end_time_s < scan.start_time_s) {
    std::ostringstream out;
    out.precision(17);
    out << "time going backwards: scan ends at " << scan.end_time_s << " s before it starts at " << scan.start_time_s
        << " s";
    throw InputError(out.str());
  }
  for (std::size_t i = 0; i < scan.points.size(); ++i) {
    const Point& p = scan.points[i];
    if (!p.position_m.allFinite()) throw InputError(PointLabel(i) + "non-finite coordinate");
    if (!std::isfinite(p.time_s)) throw InputError(PointLabel(i) + "non-finite time");
    if (scan.has_point_time && (p.time_s < scan.start_time_s || p.time_s > scan.end_time_s)) {
      std::ostringstream out;
      out.precision(17);
      out << PointLabel(i) << "time " << p.time_s << " s outside the scan window [" << scan.start_time_s << ", "
          << scan.end_time_s << "] s";
      throw InputError(out.str());
    }
  }
}

BodyScan DeskewScan(const RawScan& scan, const MountQuery& T_body_lidar_at, const MotionQuery& T_world_body_at,
                    const RangeLimits& limits) {
  ValidateRawScan(scan);
  BodyScan out;
  out.reference_time_s = scan.end_time_s;
  out.points.reserve(scan.points.size());
  const Eigen::Isometry3d T_body_world_ref = T_world_body_at(scan.end_time_s).inverse();
  // Points of one firing share a time: reuse the transform while it does not change.
  double cached_time = std::nan("");
  Eigen::Isometry3d T_bodyref_lidar = Eigen::Isometry3d::Identity();
  for (const Point& p : scan.points) {
    const double range = p.position_m.norm();
    if (range < limits.min_range_m || range > limits.max_range_m) {
      ++out.dropped_out_of_range;
      continue;
    }
    if (!(p.time_s == cached_time)) {
      // T_body(t_ref)_lidar(t_i) = T_world_body(t_ref)^-1 * T_world_body(t_i) * T_body_lidar(t_i)
      T_bodyref_lidar = T_body_world_ref * T_world_body_at(p.time_s) * T_body_lidar_at(p.time_s);
      cached_time = p.time_s;
    }
    Point body = p;
    body.position_m = T_bodyref_lidar * p.position_m;
    out.points.push_back(body);
  }
  return out;
}

}  // namespace unimap
