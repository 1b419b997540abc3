#pragma once
// One self-contained HTML page: metrics table and the figures as data URIs.
#include <string>
#include <vector>

#include "eval/TrajectoryFigures.hpp"
#include "eval/TrajectoryMetrics.hpp"

namespace unimap::eval {

// Where the evaluated trajectories came from (shown in the report).
struct ReportSources {
  std::string estimate_file;  // path of the estimate as given
  std::string truth_file;     // path of the ground truth as given
};

// The HTML text: sources, a metrics table (key, value, meaning) and one
// <img src="data:image/png;base64,..."> per figure. No external resources.
std::string RenderHtmlReport(const TrajectoryMetrics& metrics, const std::vector<Figure>& figures,
                             const ReportSources& sources);

// text with & < > " ' replaced by entities.
std::string EscapeHtml(const std::string& text);

}  // namespace unimap::eval
