#pragma once
// The files of a run folder a report is built from.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "report/ReportOptions.hpp"

namespace unimap::report {

// What ResolveRunFolder found.
struct RunFolder {
  std::filesystem::path folder;         // the run folder
  nlohmann::ordered_json run;           // run.json (an empty object when absent)
  nlohmann::ordered_json metrics;       // metrics.json (an empty object when absent)
  std::filesystem::path estimate_file;  // empty: none
  std::filesystem::path odometry_file;  // empty: none
  std::filesystem::path truth_file;     // empty: none
  std::filesystem::path map_file;       // empty: none
  std::filesystem::path loops_file;     // loop_closures.csv, empty: none
  std::vector<std::string> notes;       // what was not found and why, for the report
};

// Reads run.json and metrics.json when present and resolves every file:
// a file named in options must exist; otherwise the estimate is
// trajectory.tum, the odometry trajectory_odometry.tum, the truth the
// groundtruth.tum of run.json's "dataset", the map map.ply, else map.pcd,
// else run.json's "localize"."map" (a .ply or .pcd prior map), each when it
// exists. Throws InputError naming the file for a missing folder, a named
// file that does not exist, invalid JSON, and a folder with neither a
// trajectory nor a map.
RunFolder ResolveRunFolder(const ReportOptions& options);

}  // namespace unimap::report
