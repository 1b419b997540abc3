#pragma once
// Writes an evaluation's files: metrics.json and the PNG figures (the
// interactive report.html is core/report's).
#include <filesystem>
#include <vector>

#include "eval/MetricRows.hpp"
#include "eval/TrajectoryEvaluation.hpp"

namespace unimap::eval {

// Metrics an evaluation writes beyond the trajectory's (e.g. the map error).
struct ReportExtras {
  std::vector<ExtraMetric> metrics;  // appended to metrics.json, in order
};

// Creates out_dir if needed and writes metrics.json, trajectory_top.png,
// trajectory_side.png, position_error.png and rotation_error.png there,
// each atomically (temp file + rename). Returns the paths written, in that
// order. Throws unimap::Error when a file cannot be written.
std::vector<std::filesystem::path> WriteEvaluationReport(const TrajectoryEvaluation& evaluation,
                                                         const std::filesystem::path& out_dir,
                                                         const ReportExtras& extras = {});

}  // namespace unimap::eval
