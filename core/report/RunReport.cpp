#include "report/RunReport.hpp"

#include "eval/AtomicFile.hpp"
#include "report/ReportHtml.hpp"
#include "report/RunFolder.hpp"

namespace unimap::report {

ReportResult WriteRunReport(const ReportOptions& options) { return WriteRunReport(ResolveRunFolder(options), options); }

ReportResult WriteRunReport(const RunFolder& folder, const ReportOptions& options) {
  const ReportData data = BuildReportData(folder, options);
  ReportResult result;
  result.file = folder.folder / "report.html";
  result.counts = data.counts;
  eval::WriteFileAtomically(result.file, RenderReportHtml(data.payload));
  return result;
}

}  // namespace unimap::report
