#include "eval/LoopClosureCheck.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "eval/TrajectoryAssociation.hpp"

namespace unimap::eval {
namespace {

// The truth at time_s, interpolated; nothing outside its span.
std::optional<Eigen::Isometry3d> TruthAt(const std::vector<StampedPose>& truth, double time_s) {
  if (truth.empty() || time_s < truth.front().time_s || time_s > truth.back().time_s) return std::nullopt;
  const auto after =
      std::lower_bound(truth.begin(), truth.end(), time_s, [](const StampedPose& p, double t) { return p.time_s < t; });
  if (after == truth.begin()) return after->T_map_body;
  return InterpolatePose(*(after - 1), *after, time_s);
}

}  // namespace

LoopClosureCheck CheckLoopClosures(const std::vector<ClaimedMotion>& claims, const std::vector<StampedPose>& truth) {
  LoopClosureCheck check;
  for (const ClaimedMotion& claim : claims) {
    const std::optional<Eigen::Isometry3d> start = TruthAt(truth, claim.start_time_s);
    const std::optional<Eigen::Isometry3d> end = TruthAt(truth, claim.end_time_s);
    if (!start || !end) continue;
    const Eigen::Isometry3d error = (start->inverse() * *end).inverse() * claim.T_start_end;
    const double translation_m = error.translation().norm();
    const double rotation_deg = Eigen::AngleAxisd(error.linear()).angle() * 180.0 / M_PI;
    ++check.checked;
    check.max_translation_error_m = std::max(check.max_translation_error_m, translation_m);
    check.max_rotation_error_deg = std::max(check.max_rotation_error_deg, rotation_deg);
    if (translation_m > check.false_translation_m || rotation_deg > check.false_rotation_deg) {
      ++check.false_closures;
      // error = truth^-1 * claim, so its translation is the claim's end position minus the truth's, in the
      // truth's end frame; rotated into the start frame it reads along the path.
      const Eigen::Vector3d offset_start = (start->inverse() * *end).linear() * error.translation();
      check.false_list.push_back({claim.start_time_s, claim.end_time_s, offset_start, rotation_deg});
    }
  }
  return check;
}

}  // namespace unimap::eval
