#include "report/RunReport.hpp"

#include "eval/AtomicFile.hpp"
#include "report/ReportHtml.hpp"
#include "report/RunFolder.hpp"
#include "unimap/Errors.hpp"

namespace unimap::report {

ReportResult WriteRunReport(const ReportOptions& options) { return WriteRunReport(ResolveRunFolder(options), options); }

ReportResult WriteRunReport(const RunFolder& folder, const ReportOptions& options) {
  ReportData data;
  try {
    data = BuildReportData(folder, options);
  } catch (const nlohmann::json::exception& e) {  // a run.json value of an unexpected type
    throw InputError("run folder " + folder.folder.string() + ": " + e.what());
  }
  ReportResult result;
  result.file = folder.folder / "report.html";
  result.counts = data.counts;
  eval::WriteFileAtomically(result.file, RenderReportHtml(data.payload));
  return result;
}

}  // namespace unimap::report
