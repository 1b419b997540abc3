#include "pipeline/Reacquirer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "estimation/So3.hpp"
#include "map/CoarseField.hpp"
#include "matching/PoseRefiner.hpp"
#include "pipeline/FieldDistanceQuery.hpp"
#include "unimap/Errors.hpp"

namespace unimap::pipeline {
namespace {

// Effective points of the search's likelihood (as the matcher's default).
constexpr double kEffectivePoints = 20.0;
// The search's prior: the prediction's covariance widened this much (10
// sigmas): the scan decides where it constrains the pose, the prediction
// where it does not (a 2D line, a corridor's length).
constexpr double kPriorWidening = 100.0;
// Its position and rotation variances at least (m^2, rad^2).
constexpr double kMinPositionVariance = 1e-2;
constexpr double kMinRotationVariance = 1e-4;

ReacquireOptions Checked(const ReacquireOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw ConfigError("", 0, "reacquire", why);
  return options;
}

}  // namespace

std::vector<Eigen::Vector3f> StridedSubset(const std::vector<Eigen::Vector3f>& points, int max_points) {
  if (max_points <= 0 || static_cast<int>(points.size()) <= max_points) return points;
  const std::size_t stride =
      (points.size() + static_cast<std::size_t>(max_points) - 1) / static_cast<std::size_t>(max_points);
  std::vector<Eigen::Vector3f> subset;
  subset.reserve(static_cast<std::size_t>(max_points));
  for (std::size_t i = 0; i < points.size(); i += stride) subset.push_back(points[i]);
  return subset;
}

bool ReacquireOptions::IsValid(std::string* why) const {
  std::string local;
  if (why == nullptr) why = &local;
  if (coarse_factor < 1 || coarse_iterations < 1 || fine_iterations < 1 || max_points < 1) {
    *why = "coarse_factor, coarse_iterations, fine_iterations and max_points must be >= 1";
    return false;
  }
  const double positive[] = {coarse_clamp_m, inlier_distance_voxels, wide_sigma_voxels, wide_sigma_rad, max_yaw_rad};
  for (const double v : positive) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      *why =
          "coarse_clamp_m, inlier_distance_voxels, wide_sigma_voxels, wide_sigma_rad and max_yaw_rad must be finite "
          "and > 0";
      return false;
    }
  }
  if (!(min_inlier_gain >= 0.0 && min_inlier_gain <= 1.0)) {
    *why = "min_inlier_gain must be in [0, 1]";
    return false;
  }
  return true;
}

Reacquirer::Reacquirer(const ReacquireOptions& options) : options_(Checked(options)) {}

double Reacquirer::InlierShare(const map::DistanceField& field, const Eigen::Isometry3d& T_map_body,
                               const std::vector<Eigen::Vector3f>& points_body) const {
  if (points_body.empty()) return 0.0;
  const float limit = static_cast<float>(options_.inlier_distance_voxels) * field.resolution();
  const Eigen::Isometry3f T = T_map_body.cast<float>();
  std::size_t inliers = 0;
  for (const Eigen::Vector3f& p : points_body) inliers += field.Distance(T * p) <= limit ? 1 : 0;
  return static_cast<double>(inliers) / static_cast<double>(points_body.size());
}

matching::Vector6d Reacquirer::GridSearch(const Eigen::Isometry3d& T_map_body_predicted,
                                          const matching::Matrix6d& predicted_covariance,
                                          const std::vector<Eigen::Vector3f>& points_body) const {
  const double cell = coarse_->resolution();
  const double position_reach =
      std::min(options_.coarse_clamp_m, 3.0 * std::sqrt(predicted_covariance.block<2, 2>(0, 0).diagonal().maxCoeff()));
  const double yaw_reach = std::min(options_.max_yaw_rad, 3.0 * std::sqrt(predicted_covariance(5, 5)));
  // Heading step: half a coarse cell at the farthest point.
  double farthest = 0.0;
  for (const Eigen::Vector3f& p : points_body) farthest = std::max(farthest, static_cast<double>(p.head<2>().norm()));
  const double position_step = 0.5 * cell;
  const double yaw_step = farthest > 0.0 ? std::max(0.5 * cell / farthest, 1e-3) : 0.01;
  const int nx = static_cast<int>(std::floor(position_reach / position_step));
  const int nyaw = static_cast<int>(std::floor(yaw_reach / yaw_step));
  const float clamp = static_cast<float>(options_.coarse_clamp_m);
  const Eigen::Matrix3d R = T_map_body_predicted.linear();
  matching::Vector6d best = matching::Vector6d::Zero();
  double best_cost = std::numeric_limits<double>::infinity();
  std::vector<Eigen::Vector3f> moved(points_body.size());
  for (int k = -nyaw; k <= nyaw; ++k) {
    // A heading change about the world's vertical, as a body-frame rotation error.
    const Eigen::Matrix3d turn = Eigen::AngleAxisd(k * yaw_step, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Vector3d dtheta = estimation::LogQ(Eigen::Quaterniond(R.transpose() * turn * R));
    const Eigen::Matrix3f rotation = (turn * R).cast<float>();
    for (std::size_t i = 0; i < points_body.size(); ++i) moved[i] = rotation * points_body[i];
    for (int i = -nx; i <= nx; ++i) {
      for (int j = -nx; j <= nx; ++j) {
        const Eigen::Vector3f t =
            (T_map_body_predicted.translation() + Eigen::Vector3d(i * position_step, j * position_step, 0.0))
                .cast<float>();
        double cost = 0.0;
        for (const Eigen::Vector3f& p : moved) {
          const float d = std::min(coarse_->Distance(p + t), clamp);
          cost += static_cast<double>(d * d);
        }
        // Ties go to the candidate nearest the prediction (the loops' order is symmetric).
        const double offset = std::abs(i) + std::abs(j) + std::abs(k);
        if (cost < best_cost - 1e-9 ||
            (std::abs(cost - best_cost) <= 1e-9 &&
             offset < std::abs(best(0) / position_step) + std::abs(best(1) / position_step))) {
          best_cost = cost;
          best << i * position_step, j * position_step, 0.0, dtheta;
        }
      }
    }
  }
  return best;
}

ReacquireResult Reacquirer::Search(const std::shared_ptr<const map::DistanceField>& field,
                                   const Eigen::Isometry3d& T_map_body_predicted,
                                   const matching::Matrix6d& predicted_covariance,
                                   const std::vector<Eigen::Vector3f>& points_body, double point_sigma_m,
                                   double fine_clamp_m) {
  ReacquireResult result;
  if (field == nullptr || field->CellCount() == 0) {
    result.reason = "no map yet";
    return result;
  }
  const std::vector<Eigen::Vector3f>& points = points_body;
  if (points.empty()) {
    result.reason = "no points";
    return result;
  }
  if (coarse_ == nullptr || coarse_source_ != field.get() || coarse_sequence_ != field->sequence()) {
    coarse_ = map::CoarsenField(*field, options_.coarse_factor, static_cast<float>(options_.coarse_clamp_m));
    coarse_source_ = field.get();
    coarse_sequence_ = field->sequence();
  }
  matching::Matrix6d flat = kPriorWidening * predicted_covariance;
  for (int i = 0; i < 6; ++i) flat(i, i) = std::max(flat(i, i), i < 3 ? kMinPositionVariance : kMinRotationVariance);
  const std::vector<int> dims = {0, 1, 2, 3, 4, 5};
  const matching::Vector6d zero = matching::Vector6d::Zero();
  // Coarse: sigma of a coarse cell, the coarse reach as the clamp.
  const matching::PoseRefiner coarse(coarse_->resolution(), options_.coarse_clamp_m, kEffectivePoints,
                                     options_.coarse_iterations);
  const matching::Vector6d start = GridSearch(T_map_body_predicted, predicted_covariance, points);
  const matching::PoseRefinement rough =
      coarse.Refine(T_map_body_predicted, zero, flat, start, dims, points, FieldDistanceQuery(coarse_, true));
  const matching::PoseRefiner fine(point_sigma_m, fine_clamp_m, kEffectivePoints, options_.fine_iterations);
  const matching::PoseRefinement refined = fine.Refine(T_map_body_predicted, zero, flat, rough.ok ? rough.mean : start,
                                                       dims, points, FieldDistanceQuery(field, true));
  if (!refined.ok) {
    result.reason = "refinement failed: " + refined.reason;
    return result;
  }
  // A pose outside the searched region is not one the search can vouch for.
  if (refined.mean.head<3>().norm() > options_.coarse_clamp_m ||
      refined.mean.tail<3>().norm() > 2.0 * options_.max_yaw_rad) {
    result.reason = "the pose found lies outside the searched region";
    return result;
  }
  result.ok = true;
  result.error = refined.mean;
  result.inliers_predicted = InlierShare(*field, T_map_body_predicted, points);
  result.inliers_found = InlierShare(*field, estimation::ApplyPoseError(T_map_body_predicted, refined.mean), points);
  return result;
}

void ReacquireOptions::VisitFields(options::FieldVisitor& v) {
  v.Field("coarse_factor", &coarse_factor, "count");
  v.Field("coarse_clamp_m", &coarse_clamp_m, "m");
  v.Field("coarse_iterations", &coarse_iterations, "count");
  v.Field("fine_iterations", &fine_iterations, "count");
  v.Field("inlier_distance_voxels", &inlier_distance_voxels, "voxels");
  v.Field("min_inlier_gain", &min_inlier_gain, "");
  v.Field("max_points", &max_points, "count");
  v.Field("wide_sigma_voxels", &wide_sigma_voxels, "voxels");
  v.Field("wide_sigma_rad", &wide_sigma_rad, "rad");
  v.Field("max_yaw_rad", &max_yaw_rad, "rad");
}

}  // namespace unimap::pipeline
