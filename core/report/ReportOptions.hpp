#pragma once
// What a report is built from and how much of it is drawn.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>

#include <Eigen/Core>

#include "eval/TrajectoryEvaluation.hpp"

namespace unimap::report {

// Distance (m) of a point in the truth's (world) frame to the true surfaces.
using SurfaceDistance = std::function<double(const Eigen::Vector3d& p_world)>;

// The inputs of a report. Files left empty are looked up in the run folder
// (RunFolder.hpp says where); a file that is named must exist.
struct ReportOptions {
  std::filesystem::path folder;           // run folder: report.html goes here; run.json, metrics.json read from it
  std::filesystem::path estimate_file;    // trajectory shown and evaluated (TUM); empty: folder/trajectory.tum
  std::filesystem::path odometry_file;    // a second estimate drawn beside it; empty: trajectory_odometry.tum if any
  std::filesystem::path truth_file;       // ground truth (TUM); empty: groundtruth.tum of run.json's dataset, if any
  std::filesystem::path map_file;         // .ply or .pcd; empty: map.ply, else map.pcd, else run.json's prior map
  eval::EvaluationOptions evaluation;     // how the estimate is compared with the truth (as metrics.json)
  std::size_t map_point_budget = 250000;  // most map points drawn (every k-th point beyond it)
  std::size_t plot_row_budget = 20000;    // most rows per plot and samples per drawn trajectory
  // Colours the map by its error when set and the truth gives an alignment
  // (points moved into the truth's frame by the ATE alignment first).
  SurfaceDistance surface_distance;

  // True when folder is set and the budgets are at least 1 (plots: 2); otherwise
  // *reason (if given) says which field is wrong.
  bool IsValid(std::string* reason = nullptr) const {
    std::string why;
    if (folder.empty()) {
      why = "folder is empty";
    } else if (map_point_budget == 0) {
      why = "map_point_budget must be at least 1";
    } else if (plot_row_budget < 2) {
      why = "plot_row_budget must be at least 2";
    }
    if (reason != nullptr) *reason = why;
    return why.empty();
  }
};

}  // namespace unimap::report
