#pragma once
// report.html: one self-contained page (no network access needed).
#include <string>

#include <nlohmann/json.hpp>

namespace unimap::report {

// The page: the embedded stylesheets, the payload (ReportData) as a
// <script type="application/json" id="report-data"> element with every '<'
// written as \u003c (so no text in it ends the element), then three.js,
// OrbitControls, dygraphs and assets/report.js, which builds the page from
// the payload. Nothing is loaded from elsewhere.
std::string RenderReportHtml(const nlohmann::ordered_json& payload);

}  // namespace unimap::report
