#pragma once
// Everything report.html shows, as the JSON its script reads.
#include <cstddef>

#include <nlohmann/json.hpp>

#include "report/MapLayer.hpp"
#include "report/ReportOptions.hpp"
#include "report/RunFolder.hpp"

namespace unimap::report {

// How much the report holds (printed by the commands, checked by the tests).
struct ReportCounts {
  std::size_t estimate_poses = 0;  // poses in the estimate file
  std::size_t truth_pairs = 0;     // estimate poses associated with the truth (0: no evaluation)
  std::size_t plot_rows = 0;       // rows of every plot (the same for each)
  std::size_t plots = 0;           // number of plots
  std::size_t loop_closures = 0;   // loop closures drawn
  MapLayerCounts map;              // map points drawn
};

// The payload and its counts.
struct ReportData {
  nlohmann::ordered_json payload;
  ReportCounts counts;
};

// Reads the folder's trajectories, truth, map and loop closures and builds
// the payload: RunSections' tables, plus "title", "folder", "notes",
// "files" [{label, path}], "map" (MapLayer, or null), "trajectories"
// [{name, label, color, count, txyz}] in the map frame (truth moved there by
// the inverse ATE alignment), "loops" {count, xyz} (or null) and "plots"
// [{id, title, ylabel, labels, colors, dashed, rows, data}], times in
// seconds since the estimate's first pose. Throws InputError for unreadable
// files; a truth that does not overlap the estimate is a note, not an error.
ReportData BuildReportData(const RunFolder& folder, const ReportOptions& options);

}  // namespace unimap::report
