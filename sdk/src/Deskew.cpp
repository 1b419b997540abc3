#include "unimap/Deskew.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap {
namespace {

std::string PointLabel(std::size_t index) { return "point " + std::to_string(index) + ": "; }

// A transform as its rotation and translation, for interpolation.
struct Knot {
  double time_s = 0.0;
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

Knot MakeKnot(double time_s, const Eigen::Isometry3d& T) {
  return Knot{time_s, Eigen::Quaterniond(T.linear()).normalized(), T.translation()};
}

// The transform a fraction s in [0, 1] of the way from a to b: translation
// linear, rotation by the normalised linear blend of the quaternions (the
// geodesic's to O(angle^3), sub-nanoradian at the angles between knots).
Eigen::Isometry3d Blend(const Knot& a, const Knot& b, double s) {
  const Eigen::Quaterniond& qa = a.rotation;
  Eigen::Quaterniond qb = b.rotation;
  if (qa.dot(qb) < 0.0) qb.coeffs() = -qb.coeffs();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond((1.0 - s) * qa.coeffs() + s * qb.coeffs()).normalized().toRotationMatrix();
  T.translation() = (1.0 - s) * a.translation + s * b.translation;
  return T;
}

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
  // T_body(t_ref)_lidar(t) = T_world_body(t_ref)^-1 * T_world_body(t) * T_body_lidar(t), exact at
  // knots kDeskewKnotSpacingS apart from the scan's start (and at its end), blended between them.
  const auto exact = [&](double time_s) {
    return MakeKnot(time_s, T_body_world_ref * T_world_body_at(time_s) * T_body_lidar_at(time_s));
  };
  const auto knot_index = [&](double time_s) {
    return static_cast<long long>(std::floor((time_s - scan.start_time_s) / kDeskewKnotSpacingS));
  };
  const auto knot_time = [&](long long index) {
    return std::min(scan.end_time_s, scan.start_time_s + static_cast<double>(index) * kDeskewKnotSpacingS);
  };
  long long cached_index = -1;
  Knot low;
  Knot high;
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
      const long long index = std::max(0LL, knot_index(p.time_s));
      if (index != cached_index) {
        if (index == cached_index + 1 && cached_index >= 0) {
          low = high;
        } else {
          low = exact(knot_time(index));
        }
        high = exact(knot_time(index + 1));
        cached_index = index;
      }
      if (low.time_s < p.time_s && p.time_s < high.time_s) {
        T_bodyref_lidar = Blend(low, high, (p.time_s - low.time_s) / (high.time_s - low.time_s));
      } else {  // on a knot, or outside the scan's window
        T_bodyref_lidar = T_body_world_ref * T_world_body_at(p.time_s) * T_body_lidar_at(p.time_s);
      }
      cached_time = p.time_s;
    }
    Point body = p;
    body.position_m = T_bodyref_lidar * p.position_m;
    out.points.push_back(body);
  }
  return out;
}

}  // namespace unimap
