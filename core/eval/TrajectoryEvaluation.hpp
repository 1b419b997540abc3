#pragma once
// One call from two trajectories to metrics and error series.
#include <vector>

#include "eval/TrajectoryAssociation.hpp"
#include "eval/TrajectoryErrors.hpp"
#include "eval/TrajectoryMetrics.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::eval {

// Options of EvaluateTrajectory.
struct EvaluationOptions {
  AssociationOptions association;        // time matching tolerance
  double segment_m = 10.0;               // RPE segment length (travelled distance), > 0
  Anchor anchor = Anchor::kYawPosition;  // how start-anchored errors place the estimate (TrajectoryErrors.hpp)
};

// Everything an evaluation produces.
struct TrajectoryEvaluation {
  TrajectoryAssociation association;  // the pairs and the truth over their span
  TrajectoryErrors errors;            // per-pose error series
  TrajectoryMetrics metrics;          // summary numbers
};

// Associates, computes errors and metrics. Throws InputError when fewer than
// two estimate poses can be associated ("do not overlap"), for invalid
// options, and for invalid poses (see AssociateTrajectories).
TrajectoryEvaluation EvaluateTrajectory(const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& truth,
                                        const EvaluationOptions& options = {});

}  // namespace unimap::eval
