#pragma once
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "graph/LoopClosureOptions.hpp"
#include "graph/SubmapMatchGrid.hpp"

namespace unimap::graph {

// One maximum of the coarse search.
struct LoopClosureCandidate {
  Eigen::Isometry3d T_submap_body = Eigen::Isometry3d::Identity();  // pose on the search lattice
  double score = 0.0;  // coarse score: mean level-0 value of the search points, in [0, 1]
};

// Work done by one search (for diagnostics and timing).
struct LoopClosureSearchStats {
  int yaw_steps = 0;          // yaw values searched
  double yaw_step_rad = 0.0;  // spacing of the yaw values (rad)
  std::size_t nodes = 0;      // branch-and-bound nodes scored (leaves included)
  std::size_t leaves = 0;     // full-resolution translations scored
};

// Branch-and-bound search (Hess et al. 2016, Algorithm 3, depth-first with
// the children of a node visited best first) for the poses of a scan in a
// submap around a guess: T = [Rz(yaw) R_guess | t_guess + r (ix, iy, iz)],
// r = the grid resolution, yaw on a lattice of +-yaw_window_rad whose step
// moves the scan's far points (90th percentile of horizontal range) by about
// one cell (clamped to [min_yaw_step_rad, max_yaw_step_rad]), ix^2 + iy^2 <=
// (radius / r)^2 and |iz| r <= z_window_m. Scores are the summed
// SubmapMatchGrid level-0 values of the scan's cells; a node's level-h score
// bounds those of its 2^h x 2^h translations. Returns up to max_candidates
// maxima, best first, no two within distinct_translation_m and
// distinct_rotation_rad of each other (a lower leaf near a kept one is
// dropped), each scoring at least min_search_score and candidate_score_ratio
// times the best. Stateless apart from its references: safe to run from
// several threads.
class LoopClosureSearch {
 public:
  // Keeps references: grid and options must outlive the search.
  LoopClosureSearch(const SubmapMatchGrid& grid, const LoopClosureOptions& options);

  // points_body: search points (finite); radius_m >= 0: xy window radius.
  std::vector<LoopClosureCandidate> Run(const std::vector<Eigen::Vector3f>& points_body,
                                        const Eigen::Isometry3d& T_submap_body_guess, double radius_m,
                                        LoopClosureSearchStats* stats) const;

 private:
  const SubmapMatchGrid& grid_;
  const LoopClosureOptions& options_;
};

}  // namespace unimap::graph
