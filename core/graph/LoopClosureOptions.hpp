#pragma once
#include <cstdint>
#include <string>

#include "options/FieldVisitor.hpp"

namespace unimap::graph {

// Settings of the loop-closure matcher (LoopClosureMatcher): a scan matched
// against one retired submap. Defaults suit submaps whose points are
// voxel-filtered at 0.05-0.1 m and scans filtered at ~0.1 m; for coarser
// submaps scale the resolutions, the kernel and inlier_distance_m with the
// submap's voxel size.
struct LoopClosureOptions {
  // --- Grids built once per submap ---
  double search_resolution_m = 0.25;  // cell edge of the coarse search grid = translation step of the search (m)
  double search_kernel_m = 0.3;       // coarse cell score falls linearly from 1 (a submap point inside the
                                      // cell) to 0 (nearest point this far from the cell) (m)
  int search_levels = 4;              // branch-and-bound levels: xy max-pooled grids over 1, 2, ..., 2^(levels-1) cells
  double fine_resolution_m = 0.1;     // cell edge of the fine distance field used to refine and score (m)
  double fine_clamp_m = 0.3;          // fine distances beyond this are not stored (they read as this) (m)
  double normal_cell_m = 0.2;         // submap normals: plane fitted to the points of a cube of this edge and
                                      // its 26 neighbours (m)
  double planarity_ratio = 0.1;       // a fit is a plane when its smallest scatter eigenvalue is at most this
                                      // times the middle one (else point-to-point residuals)

  // --- Scan subsets ---
  double search_voxel_m = 0.25;  // voxel edge of the scan subset used by the search (m)
  int max_search_points = 400;   // at most this many search points (seeded random subset)
  double refine_voxel_m = 0.1;   // voxel edge of the scan subset used to refine and score (m)
  int max_refine_points = 2000;  // at most this many refinement points
  int min_scan_points = 30;      // fewer refinement points than this: not matched
  std::uint64_t seed = 1;        // subset selection seed (deterministic results)

  // --- Search window around the guess (xy radius: Match's argument) ---
  double z_window_m = 0.5;             // translations searched in z: within +- this of the guess (m)
  double yaw_window_rad = 0.2618;      // yaw searched within +- this of the guess (rad, 15 deg)
  double min_yaw_step_rad = 0.01;      // yaw step = search_resolution_m / scan extent, at least this (rad)
  double max_yaw_step_rad = 0.035;     // ... and at most this (rad)
  double ambiguity_margin_m = 1.0;     // the xy window reaches this much beyond the radius, so repeated
                                       // structure just outside it is seen; the best match must still lie
                                       // within the radius (m)
  int max_candidates = 10;             // distinct search maxima refined (the best and its alternatives)
  double min_search_score = 0.3;       // search maxima below this coarse score (0-1) are ignored
  double candidate_score_ratio = 0.7;  // ... and below this fraction of the best coarse score

  // --- Refinement (6-DOF Gauss-Newton on the fine field) ---
  int max_iterations = 30;  // Levenberg-Marquardt iterations per search maximum at most
  double huber_m = 0.05;    // Huber threshold on point residuals (m)

  // --- Acceptance ---
  double inlier_distance_m = 0.1;         // a refined scan point within this of the submap surface is an inlier (m)
  double min_score = 0.6;                 // accepted only when the inlier fraction reaches this
  double distinct_translation_m = 0.5;    // an alternative is distinct when farther than this from the best (m) ...
  double distinct_rotation_rad = 0.0873;  // ... or rotated by more than this (rad, 5 deg)
  double ambiguity_floor = 0.05;          // fraction of the points added to both exclusive-inlier fractions (see
                                          // LoopClosureMatcher): alignments differing in fewer points read as ambiguous
  double max_ambiguity = 0.5;          // accepted only when the ambiguity of every distinct alternative is at most this
  double max_position_sigma_m = 0.25;  // accepted only when every position standard deviation is at most this (m)
  double max_rotation_sigma_rad = 0.05;  // ... and every rotation standard deviation at most this (rad)

  // --- Covariance of the accepted pose ---
  double effective_points = 50.0;         // the Gauss-Newton covariance sigma^2 H^-1 is inflated by
                                          // inliers / effective_points (neighbouring points are correlated)
  double min_sigma_position_m = 0.02;     // added in quadrature to the position standard deviations (m)
  double min_sigma_rotation_rad = 0.003;  // ... and to the rotation ones (rad)

  // Every field by name, for the platform file's `mapper:` section (SettingsOverrides).
  void VisitFields(options::FieldVisitor& v);
  // True when every field is in range; otherwise false with the reason in
  // *why (when why is not null).
  bool IsValid(std::string* why) const;
  // The defaults for submaps voxel-filtered at voxel_m: for voxels above
  // 0.1 m the fine-scale lengths (fine grid, clamp, normal cell, refinement
  // voxel, Huber, inlier distance) grow with the voxel, and for voxels above
  // the search cell the search grid, kernel and voxel do too.
  static LoopClosureOptions ForVoxel(double voxel_m);
};

}  // namespace unimap::graph
