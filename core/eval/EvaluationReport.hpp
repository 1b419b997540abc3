#pragma once
// Writes an evaluation's files: metrics.json, the PNG figures, report.html.
#include <filesystem>
#include <vector>

#include "eval/HtmlReport.hpp"
#include "eval/TrajectoryEvaluation.hpp"

namespace unimap::eval {

// Creates out_dir if needed and writes metrics.json, trajectory_top.png,
// trajectory_side.png, position_error.png, rotation_error.png and
// report.html there, each atomically (temp file + rename). Returns the paths
// written, in that order. Throws unimap::Error when a file cannot be written.
// extras: what the report shows beyond the trajectory (e.g. the map error;
// its metrics also go to metrics.json).
std::vector<std::filesystem::path> WriteEvaluationReport(const TrajectoryEvaluation& evaluation,
                                                         const ReportSources& sources,
                                                         const std::filesystem::path& out_dir,
                                                         const ReportExtras& extras = {});

}  // namespace unimap::eval
