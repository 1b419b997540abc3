#include "eval/TrajectoryEvaluation.hpp"

#include <cmath>
#include <sstream>

#include "unimap/Errors.hpp"

namespace unimap::eval {
namespace {

// "[t0, t1] s (n poses)" or "no poses".
std::string Span(const std::vector<StampedPose>& poses) {
  if (poses.empty()) return "no poses";
  std::ostringstream out;
  out.precision(15);
  out << "[" << poses.front().time_s << ", " << poses.back().time_s << "] s (" << poses.size() << " poses)";
  return out.str();
}

}  // namespace

TrajectoryEvaluation EvaluateTrajectory(const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& truth,
                                        const EvaluationOptions& options) {
  if (!(options.segment_m > 0.0) || !std::isfinite(options.segment_m)) {
    throw InputError("segment length must be positive and finite");
  }
  TrajectoryEvaluation result;
  result.association = AssociateTrajectories(estimate, truth, options.association);
  if (result.association.pairs.size() < 2) {
    std::ostringstream out;
    out << "estimate and truth do not overlap: " << result.association.pairs.size()
        << " estimate pose(s) associated (need >= 2); estimate spans " << Span(estimate) << ", truth spans "
        << Span(truth) << ", " << result.association.skipped_in_gap << " skipped for truth samples more than "
        << options.association.max_time_diff_s << " s away";
    throw InputError(out.str());
  }
  result.errors = ComputeTrajectoryErrors(result.association, options.anchor);
  result.metrics = ComputeTrajectoryMetrics(result.association, result.errors, options.association.max_time_diff_s,
                                            options.segment_m);
  return result;
}

}  // namespace unimap::eval
