#include "FolderReport.hpp"

#include <iostream>
#include <memory>
#include <optional>

#include "MapEvaluation.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {

report::ReportResult WriteFolderReport(report::ReportOptions options, const std::string& world_option) {
  const report::RunFolder folder = report::ResolveRunFolder(options);
  std::optional<std::filesystem::path> world;
  if (!folder.truth_file.empty() || !world_option.empty()) world = ResolveWorldFile(world_option, folder.truth_file);
  if (world) {
    auto loaded = std::make_shared<const sim::World>(LoadWorldFile(*world));
    if (loaded->size() > 0) {
      options.surface_distance = [loaded](const Eigen::Vector3d& p_world) { return loaded->SurfaceDistance(p_world); };
    }
  }
  return report::WriteRunReport(folder, options);
}

void WriteRunReportOrWarn(const std::filesystem::path& folder) {
  try {
    report::ReportOptions options;
    options.folder = folder;
    const report::ReportResult result = WriteFolderReport(options);
    std::cout << "report: " << result.file.string() << '\n';
  } catch (const Error& e) {
    std::cerr << "warning: report.html not written: " << e.what() << '\n';
  }
}

}  // namespace unimap::cli
