#include "eval/TrajectoryAssociation.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>
#include <string>

#include "estimation/So3.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

std::string Describe(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// Throws InputError unless every pose is finite, has a unit rotation and the
// times never decrease. which: "estimate" or "truth".
void Validate(const std::vector<StampedPose>& poses, const char* which) {
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const StampedPose& pose = poses[i];
    const std::string where = std::string(which) + " pose " + std::to_string(i);
    if (!std::isfinite(pose.time_s) || !pose.T_map_body.matrix().allFinite()) {
      throw InputError(where + ": non-finite time or pose");
    }
    const Eigen::Matrix3d R = pose.T_map_body.linear();
    if (!(R.transpose() * R).isApprox(Eigen::Matrix3d::Identity(), 1e-6)) {
      throw InputError(where + ": rotation is not orthonormal");
    }
    if (i > 0 && pose.time_s < poses[i - 1].time_s) {
      throw InputError(where + ": time going backwards (" + Describe(pose.time_s) + " s after " +
                       Describe(poses[i - 1].time_s) + " s)");
    }
  }
}

}  // namespace

Eigen::Isometry3d InterpolatePose(const StampedPose& a, const StampedPose& b, double time_s) {
  const double span = b.time_s - a.time_s;
  const double s = span > 0.0 ? (time_s - a.time_s) / span : 0.0;
  if (s == 0.0) return a.T_map_body;
  return estimation::InterpolatePose(a.T_map_body, b.T_map_body, s);
}

TrajectoryAssociation AssociateTrajectories(const std::vector<StampedPose>& estimate,
                                            const std::vector<StampedPose>& truth, const AssociationOptions& options) {
  if (!(options.max_time_diff_s > 0.0) || !std::isfinite(options.max_time_diff_s)) {
    throw InputError("max_time_diff_s must be positive and finite (got " + Describe(options.max_time_diff_s) + ")");
  }
  Validate(estimate, "estimate");
  Validate(truth, "truth");

  TrajectoryAssociation result;
  if (truth.empty()) {
    result.skipped_outside_span = estimate.size();
    return result;
  }
  const auto by_time = [](double t, const StampedPose& p) { return t < p.time_s; };
  for (const StampedPose& est : estimate) {
    const double t = est.time_s;
    if (t < truth.front().time_s || t > truth.back().time_s) {
      ++result.skipped_outside_span;
      continue;
    }
    // hi: first truth sample after t; lo: the last one at or before t.
    const auto hi = std::upper_bound(truth.begin(), truth.end(), t, by_time);
    const auto lo = std::prev(hi);
    AssociatedPose pair;
    pair.time_s = t;
    pair.T_est_body = est.T_map_body;
    if (lo->time_s == t || hi == truth.end()) {
      pair.T_true_body = lo->T_map_body;  // exact hit (hi == end implies t == last time)
    } else {
      if (t - lo->time_s > options.max_time_diff_s || hi->time_s - t > options.max_time_diff_s) {
        ++result.skipped_in_gap;
        continue;
      }
      pair.T_true_body = InterpolatePose(*lo, *hi, t);
    }
    result.pairs.push_back(pair);
  }
  if (result.pairs.empty()) return result;

  // The truth over the associated span: interpolated ends, raw samples between.
  const double t0 = result.pairs.front().time_s;
  const double t1 = result.pairs.back().time_s;
  result.truth_span.push_back({t0, result.pairs.front().T_true_body});
  for (const StampedPose& sample : truth) {
    if (sample.time_s > t0 && sample.time_s < t1) result.truth_span.push_back(sample);
  }
  if (t1 > t0) result.truth_span.push_back({t1, result.pairs.back().T_true_body});
  return result;
}

}  // namespace unimap::eval
