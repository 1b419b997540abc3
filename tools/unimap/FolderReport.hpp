#pragma once
// report.html of a folder from the command line: report::WriteRunReport
// with the map error against the simulated world when one is found.
#include <filesystem>
#include <string>

#include "report/RunReport.hpp"

namespace unimap::cli {

// Resolves the folder's files (report::ResolveRunFolder), takes the world
// from world_option or the world.yaml beside the truth (ResolveWorldFile)
// to colour the map by its error, and writes folder/report.html. Throws
// unimap::Error (InputError / ConfigError naming the file) when it cannot.
report::ReportResult WriteFolderReport(report::ReportOptions options, const std::string& world_option = "");

// WriteFolderReport(folder) for the end of a run: prints "report: FILE" or,
// when the report cannot be built, a warning (the run's other outputs stand).
void WriteRunReportOrWarn(const std::filesystem::path& folder);

}  // namespace unimap::cli
