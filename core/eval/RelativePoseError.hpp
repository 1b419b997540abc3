#pragma once
// Relative pose error over segments of travelled distance (docs/evaluation.md).
#include <cstddef>
#include <optional>

#include "eval/TrajectoryAssociation.hpp"
#include "eval/TrajectoryErrors.hpp"

namespace unimap::eval {

// Averages over every segment; empty optionals when the path is shorter than
// one segment (no segment exists).
struct RelativePoseError {
  std::size_t segments = 0;             // number of (start, end) pairs averaged
  std::optional<double> trans_percent;  // mean 100 |t(E)| / d over segments
  std::optional<double> rot_deg_per_m;  // mean angle(E) [deg] / d over segments
};

// For each start index i, the end j is the first later index whose truth
// distance travelled since i (errors.poses[].distance_m) is >= segment_m.
// E = (T_true(i)^-1 T_true(j))^-1 (T_est(i)^-1 T_est(j)); d = travelled
// distance from i to j. Throws InputError for segment_m <= 0 or not finite,
// or when errors and association differ in size.
RelativePoseError ComputeRelativePoseError(const TrajectoryAssociation& association, const TrajectoryErrors& errors,
                                           double segment_m);

}  // namespace unimap::eval
