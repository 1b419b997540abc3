#pragma once
// One self-contained HTML page: metrics table and the figures as data URIs.
#include <string>
#include <utility>
#include <vector>

#include "eval/MetricRows.hpp"
#include "eval/TrajectoryFigures.hpp"
#include "eval/TrajectoryMetrics.hpp"

namespace unimap::eval {

// Where the evaluated trajectories came from (shown in the report).
struct ReportSources {
  std::string estimate_file;  // path of the estimate as given
  std::string truth_file;     // path of the ground truth as given
};

// What a report shows beyond the trajectory (e.g. the map error).
struct ReportExtras {
  std::vector<ExtraMetric> metrics;                          // appended to metrics.json and the table
  std::vector<std::pair<std::string, std::string>> sources;  // (label, path) shown below the table
};

// The HTML text: sources, a metrics table (key, value, meaning; the extra
// metrics' rows last, their sources below it) and one
// <img src="data:image/png;base64,..."> per figure. No external resources.
std::string RenderHtmlReport(const TrajectoryMetrics& metrics, const std::vector<Figure>& figures,
                             const ReportSources& sources, const ReportExtras& extras = {});

// text with & < > " ' replaced by entities.
std::string EscapeHtml(const std::string& text);

}  // namespace unimap::eval
