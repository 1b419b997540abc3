#include "report/ReportHtml.hpp"

#include "report/ReportAssets.hpp"

namespace unimap::report {
namespace {

std::string EscapeHtml(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string Script(std::string_view code) { return "<script>\n" + std::string(code) + "\n</script>\n"; }

}  // namespace

std::string RenderReportHtml(const nlohmann::ordered_json& payload) {
  const ReportAssets& assets = EmbeddedAssets();
  const std::string json = payload.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
  std::string safe_json;
  safe_json.reserve(json.size());
  for (const char c : json) {
    if (c == '<') {
      safe_json += "\\u003c";  // only inside strings: JSON has no '<' elsewhere
    } else {
      safe_json += c;
    }
  }
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
      EscapeHtml(payload.value("title", std::string("unimap report"))) + "</title>\n<style>\n" +
      std::string(assets.dygraphs_css) + "\n</style>\n<style>\n" + std::string(assets.report_css) +
      "\n</style>\n</head>\n<body>\n<noscript>This report is drawn by JavaScript (inlined in the file; no "
      "network needed): enable JavaScript to see it.</noscript>\n<div id=\"report\"></div>\n"
      "<script type=\"application/json\" id=\"report-data\">" +
      safe_json + "</script>\n";
  html += Script(assets.three_js);
  html += Script(assets.orbit_controls_js);
  html += Script(assets.dygraphs_js);
  html += Script(assets.viewer_js);
  html += Script(assets.report_js);
  html += "</body>\n</html>\n";
  return html;
}

}  // namespace unimap::report
