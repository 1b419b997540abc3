#include "eval/RelativePoseError.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "estimation/So3.hpp"
#include "unimap/Errors.hpp"

namespace unimap::eval {

RelativePoseError ComputeRelativePoseError(const TrajectoryAssociation& association, const TrajectoryErrors& errors,
                                           double segment_m) {
  if (!(segment_m > 0.0) || !std::isfinite(segment_m)) {
    throw InputError("segment length must be positive and finite (got " + std::to_string(segment_m) + ")");
  }
  const std::vector<AssociatedPose>& pairs = association.pairs;
  if (pairs.size() != errors.poses.size()) {
    throw InputError("relative pose error: association and error series differ in size");
  }
  std::vector<double> distance(pairs.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) distance[k] = errors.poses[k].distance_m;

  RelativePoseError result;
  double sum_trans_percent = 0.0;
  double sum_rot_deg_per_m = 0.0;
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    // j: first index with distance[j] - distance[i] >= segment_m (distance is non-decreasing).
    std::size_t j = static_cast<std::size_t>(
        std::lower_bound(distance.begin() + static_cast<std::ptrdiff_t>(i), distance.end(), distance[i] + segment_m) -
        distance.begin());
    while (j < pairs.size() && distance[j] - distance[i] < segment_m) ++j;
    while (j > i + 1 && distance[j - 1] - distance[i] >= segment_m) --j;
    if (j >= pairs.size()) break;  // later starts cannot reach a full segment either
    const double d = distance[j] - distance[i];
    const Eigen::Isometry3d delta_true = pairs[i].T_true_body.inverse() * pairs[j].T_true_body;
    const Eigen::Isometry3d delta_est = pairs[i].T_est_body.inverse() * pairs[j].T_est_body;
    const Eigen::Isometry3d E = delta_true.inverse() * delta_est;
    sum_trans_percent += 100.0 * E.translation().norm() / d;
    const double angle_rad = estimation::LogQ(Eigen::Quaterniond(E.linear())).norm();
    sum_rot_deg_per_m += angle_rad * 180.0 / M_PI / d;
    ++result.segments;
  }
  if (result.segments > 0) {
    const double n = static_cast<double>(result.segments);
    result.trans_percent = sum_trans_percent / n;
    result.rot_deg_per_m = sum_rot_deg_per_m / n;
  }
  return result;
}

}  // namespace unimap::eval
