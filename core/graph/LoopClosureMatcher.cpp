#include "graph/LoopClosureMatcher.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "graph/LoopClosureRefiner.hpp"
#include "graph/LoopClosureSearch.hpp"
#include "matching/VoxelDownsampler.hpp"
#include "unimap/Errors.hpp"

namespace unimap::graph {

namespace {

// Rotation angle between two poses (rad).
double RotationAngle(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

bool Distinct(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, const LoopClosureOptions& options) {
  return (a.translation() - b.translation()).norm() > options.distinct_translation_m ||
         RotationAngle(a, b) > options.distinct_rotation_rad;
}

std::string Format(const char* format, double a, double b) {
  char text[160];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

}  // namespace

LoopClosureMatcher::LoopClosureMatcher(const std::vector<Eigen::Vector3f>& submap_points,
                                       const LoopClosureOptions& options)
    : options_(options) {
  std::string why;
  if (!options.IsValid(&why)) throw ConfigError("", 0, "", "loop closure options: " + why);
  if (submap_points.empty()) throw InputError("LoopClosureMatcher: the submap has no points");
  for (const Eigen::Vector3f& p : submap_points) {
    if (!p.allFinite()) throw InputError("LoopClosureMatcher: the submap has a non-finite point");
  }
  grid_ = std::make_unique<SubmapMatchGrid>(submap_points, options.search_resolution_m, options.search_kernel_m,
                                            options.search_levels);
  field_ = std::make_unique<LoopClosureDistanceField>(submap_points, options.fine_resolution_m, options.fine_clamp_m,
                                                      options.normal_cell_m, options.planarity_ratio);
}

LoopClosureMatcher::~LoopClosureMatcher() = default;

std::size_t LoopClosureMatcher::MemoryBytes() const {
  return sizeof(*this) + grid_->MemoryBytes() + field_->MemoryBytes();
}

LoopClosureResult LoopClosureMatcher::Match(const std::vector<Eigen::Vector3f>& points_body,
                                            const Eigen::Isometry3d& T_submap_body_guess,
                                            double search_radius_m) const {
  if (!T_submap_body_guess.matrix().allFinite()) throw InputError("LoopClosureMatcher: the guess is not finite");
  if (!(std::isfinite(search_radius_m) && search_radius_m >= 0.0)) {
    throw InputError("LoopClosureMatcher: the search radius must be finite and >= 0");
  }
  LoopClosureResult result;
  result.T_submap_body = T_submap_body_guess;

  std::vector<Eigen::Vector3f> finite;
  finite.reserve(points_body.size());
  for (const Eigen::Vector3f& p : points_body) {
    if (p.allFinite()) finite.push_back(p);
  }
  const std::vector<Eigen::Vector3f> refine_points =
      matching::VoxelDownsample(finite, options_.refine_voxel_m, options_.max_refine_points, options_.seed);
  if (static_cast<int>(refine_points.size()) < options_.min_scan_points) {
    result.reason = "too few scan points (" + std::to_string(refine_points.size()) + " after filtering, need " +
                    std::to_string(options_.min_scan_points) + ")";
    return result;
  }
  const std::vector<Eigen::Vector3f> search_points =
      matching::VoxelDownsample(finite, options_.search_voxel_m, options_.max_search_points, options_.seed);

  // 1. Coarse search in the window widened by the ambiguity margin.
  const LoopClosureSearch search(*grid_, options_);
  const std::vector<LoopClosureCandidate> maxima =
      search.Run(search_points, T_submap_body_guess, search_radius_m + options_.ambiguity_margin_m, nullptr);
  if (maxima.empty()) {
    result.reason = "no search maximum above min_search_score";
    return result;
  }

  // 2. Refine every maximum (alternatives as thoroughly as the best, so
  // that their scores compare fairly); the best by score.
  const LoopClosureRefiner refiner(*field_, options_);
  std::vector<LoopClosureRefinement> refined;
  std::string failure;
  for (const LoopClosureCandidate& maximum : maxima) {
    LoopClosureRefinement r = refiner.Refine(refine_points, maximum.T_submap_body, options_.max_iterations);
    if (r.ok) {
      refined.push_back(std::move(r));
    } else {
      failure = r.reason;
    }
  }
  result.candidates = static_cast<int>(refined.size());
  if (refined.empty()) {
    result.reason = "refinement failed: " + failure;
    return result;
  }
  std::stable_sort(refined.begin(), refined.end(),
                   [](const LoopClosureRefinement& a, const LoopClosureRefinement& b) { return a.score > b.score; });
  const LoopClosureRefinement& best = refined.front();
  result.T_submap_body = best.T_submap_body;
  result.score = best.score;
  result.covariance = best.covariance;

  // Ambiguity against every distinct alternative B of the best A: the
  // points only A explains against those only B explains (the points both
  // or neither explain tell them apart no better), each as a fraction of
  // the points plus ambiguity_floor.
  const std::vector<std::uint8_t>& best_inliers = best.inlier_mask;
  const double n = static_cast<double>(refine_points.size());
  for (std::size_t i = 1; i < refined.size(); ++i) {
    if (!Distinct(refined[i].T_submap_body, best.T_submap_body, options_)) continue;
    const std::vector<std::uint8_t>& inliers = refined[i].inlier_mask;
    int only_best = 0;
    int only_alternative = 0;
    for (std::size_t k = 0; k < best_inliers.size(); ++k) {
      only_best += best_inliers[k] > inliers[k] ? 1 : 0;
      only_alternative += inliers[k] > best_inliers[k] ? 1 : 0;
    }
    const double ambiguity =
        (only_alternative / n + options_.ambiguity_floor) / (only_best / n + options_.ambiguity_floor);
    result.ambiguity = std::max(result.ambiguity, ambiguity);
  }

  // 3. Acceptance.
  const double shift_m = (best.T_submap_body.translation() - T_submap_body_guess.translation()).head<2>().norm();
  const Eigen::Vector3d position_sigma = best.covariance.diagonal().head<3>().cwiseSqrt();
  const Eigen::Vector3d rotation_sigma = best.covariance.diagonal().tail<3>().cwiseSqrt();
  if (best.score < options_.min_score) {
    result.reason = Format("score %.3f below min_score %.3f", best.score, options_.min_score);
  } else if (result.ambiguity > options_.max_ambiguity) {
    result.reason = Format("ambiguous: a distinct alignment explains nearly as much, ambiguity %.3f (max %.3f)",
                           result.ambiguity, options_.max_ambiguity);
  } else if (shift_m > search_radius_m + options_.search_resolution_m) {
    result.reason =
        Format("best alignment %.2f m from the guess, outside the search radius %.2f m", shift_m, search_radius_m);
  } else if (position_sigma.maxCoeff() > options_.max_position_sigma_m ||
             rotation_sigma.maxCoeff() > options_.max_rotation_sigma_rad) {
    result.reason = Format("degenerate: position sigma %.3f m, rotation sigma %.4f rad", position_sigma.maxCoeff(),
                           rotation_sigma.maxCoeff());
  } else {
    result.accepted = true;
    result.reason = Format("accepted: score %.3f, ambiguity %.3f", best.score, result.ambiguity);
  }
  return result;
}

}  // namespace unimap::graph
