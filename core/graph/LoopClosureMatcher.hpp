#pragma once
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "graph/LoopClosureDistanceField.hpp"
#include "graph/LoopClosureOptions.hpp"
#include "graph/SubmapMatchGrid.hpp"

namespace unimap::graph {

using Matrix6d = Eigen::Matrix<double, 6, 6>;

// Outcome of matching one scan against one submap.
struct LoopClosureResult {
  bool accepted = false;  // the match passed the score, ambiguity, radius and conditioning checks
  std::string reason;     // why not, or a short summary when accepted
  Eigen::Isometry3d T_submap_body = Eigen::Isometry3d::Identity();  // refined alignment (the best one found,
                                                                    // also when rejected; the guess if none)
  double score = 0.0;      // fraction of the scan's refinement points within inlier_distance_m of the
                           // submap surface after refinement
  double ambiguity = 0.0;  // largest, over the refined alternatives distinct from the best, of
                           // (only_alternative + floor) / (only_best + floor): 1 = fully ambiguous (see
                           // LoopClosureMatcher); 0 when the search left no distinct alternative
  Matrix6d covariance = Matrix6d::Identity();  // of T_submap_body, order [dp (submap frame), dtheta (body
                                               // frame, right)] as RelativePoseCost; SPD
  int candidates = 0;                          // search maxima refined
};

// Loop closure of a scan against a retired submap (docs/design.md 1.5):
// 1. search: branch and bound (LoopClosureSearch) over x, y, z and yaw on the
//    coarse SubmapMatchGrid with a voxel-filtered subset of the scan, in a
//    window of radius search_radius_m + ambiguity_margin_m (xy),
//    +-z_window_m and +-yaw_window_rad around the guess; it keeps up to
//    max_candidates distinct maxima;
// 2. refine each maximum in 6-DOF (LoopClosureRefiner: point-to-plane on
//    the fine LoopClosureDistanceField, all maxima alike so their scores
//    compare fairly) and score it (inlier fraction); the best scores most;
// 3. accept the best A only when its score >= min_score, no distinct
//    alternative B (farther than distinct_translation_m or rotated by more
//    than distinct_rotation_rad) explains nearly as much: with only_best and
//    only_alternative the fractions of the points that are inliers of A but
//    not of B and of B but not of A (points both or neither explain do not
//    tell them apart), ambiguity = (only_alternative + ambiguity_floor) /
//    (only_best + ambiguity_floor) <= max_ambiguity (repeated structure:
//    pillars, doors, train cars give ~1; a plain score ratio would be
//    dominated by the floor and walls every shift along them explains);
//    A lies within the search radius (+ search_resolution_m: a better match
//    just outside means the one inside is not unique); and its covariance is
//    well conditioned (no sliding along a featureless corridor).
// Repeated structure whose period exceeds search_radius_m +
// ambiguity_margin_m cannot be told apart from a unique match.
// Immutable after construction: Match may run from several threads.
class LoopClosureMatcher {
 public:
  // Precomputes the grids from the submap's points (submap frame). Throws
  // unimap::ConfigError for invalid options and unimap::InputError when the
  // points are empty, hold a non-finite value, or span too large a box.
  LoopClosureMatcher(const std::vector<Eigen::Vector3f>& submap_points, const LoopClosureOptions& options);
  ~LoopClosureMatcher();
  LoopClosureMatcher(const LoopClosureMatcher&) = delete;
  LoopClosureMatcher& operator=(const LoopClosureMatcher&) = delete;

  // Matches a scan (body frame; non-finite points are skipped) around
  // T_submap_body_guess. An empty scan (or too few points) gives
  // accepted = false with the reason. Throws unimap::InputError when the
  // guess is not finite or search_radius_m is negative or not finite.
  LoopClosureResult Match(const std::vector<Eigen::Vector3f>& points_body, const Eigen::Isometry3d& T_submap_body_guess,
                          double search_radius_m) const;

  std::size_t MemoryBytes() const;  // approximate footprint of the grids (bytes)
  const LoopClosureOptions& options() const { return options_; }

 private:
  LoopClosureOptions options_;
  std::unique_ptr<SubmapMatchGrid> grid_;
  std::unique_ptr<LoopClosureDistanceField> field_;
};

}  // namespace unimap::graph
