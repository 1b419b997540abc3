#include "eval/HtmlReport.hpp"

#include "eval/Base64.hpp"
#include "eval/MetricRows.hpp"

namespace unimap::eval {

std::string EscapeHtml(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string RenderHtmlReport(const TrajectoryMetrics& metrics, const std::vector<Figure>& figures,
                             const ReportSources& sources, const ReportExtras& extras) {
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<title>unimap trajectory evaluation</title>\n<style>\n"
      "body { font-family: sans-serif; margin: 2em; max-width: 1100px; }\n"
      "table { border-collapse: collapse; }\n"
      "td, th { border: 1px solid #ccc; padding: 4px 10px; text-align: left; }\n"
      "td.v { font-family: monospace; text-align: right; }\n"
      "img { max-width: 100%; border: 1px solid #ddd; }\n"
      "</style>\n</head>\n<body>\n<h1>Trajectory evaluation</h1>\n";
  html += "<p>Estimate: <code>" + EscapeHtml(sources.estimate_file) + "</code><br>\nTruth: <code>" +
          EscapeHtml(sources.truth_file) + "</code></p>\n";
  html += "<p>Definitions: docs/evaluation.md. Full-precision values: metrics.json.</p>\n";
  html += "<table>\n<tr><th>key</th><th>value</th><th>meaning</th></tr>\n";
  std::vector<MetricRow> rows = DescribeMetrics(metrics);
  for (const ExtraMetric& m : extras.metrics) rows.push_back(m.row);
  for (const MetricRow& row : rows) {
    html += "<tr><td><code>" + EscapeHtml(row.key) + "</code></td><td class=\"v\">" + EscapeHtml(row.value) +
            "</td><td>" + EscapeHtml(row.meaning) + "</td></tr>\n";
  }
  html += "</table>\n";
  if (!extras.sources.empty()) {
    html += "<p>";
    for (std::size_t i = 0; i < extras.sources.size(); ++i) {
      if (i > 0) html += "<br>\n";
      html += EscapeHtml(extras.sources[i].first) + ": <code>" + EscapeHtml(extras.sources[i].second) + "</code>";
    }
    html += "</p>\n";
  }
  for (const Figure& figure : figures) {
    html += "<h2>" + EscapeHtml(figure.file_name) + "</h2>\n<p>" + EscapeHtml(figure.caption) + "</p>\n";
    html += "<img alt=\"" + EscapeHtml(figure.file_name) + "\" src=\"data:image/png;base64," +
            EncodeBase64(figure.png) + "\">\n";
  }
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace unimap::eval
