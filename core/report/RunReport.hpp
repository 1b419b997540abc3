#pragma once
// Builds a run folder's report.html (`unimap report RUN_DIR`, and the end of
// `unimap run`, `localize`, `demo` and `evaluate`).
#include <filesystem>

#include "report/ReportData.hpp"
#include "report/ReportOptions.hpp"
#include "report/RunFolder.hpp"

namespace unimap::report {

// Where the report went and what it holds.
struct ReportResult {
  std::filesystem::path file;  // options.folder / "report.html"
  ReportCounts counts;
};

// ResolveRunFolder, BuildReportData, RenderReportHtml, then writes
// folder/report.html atomically. Throws InputError for unusable inputs
// (see ResolveRunFolder) and unimap::Error when the file cannot be written.
ReportResult WriteRunReport(const ReportOptions& options);
// The same for a folder already resolved with these options.
ReportResult WriteRunReport(const RunFolder& folder, const ReportOptions& options);

}  // namespace unimap::report
