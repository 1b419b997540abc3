// `unimap report RUN_DIR`: (re)builds RUN_DIR/report.html from a run's
// outputs (run.json, metrics.json, trajectories, map, loop closures), or
// from any folder holding a TUM trajectory and / or a map (other tools' runs).
#include <iostream>
#include <memory>
#include <string>

#include "Commands.hpp"
#include "FolderReport.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {
namespace {

struct ReportCliOptions {
  std::string folder;    // the run folder (report.html goes here)
  std::string estimate;  // trajectory (TUM); empty: folder/trajectory.tum
  std::string odometry;  // second trajectory (TUM); empty: folder/trajectory_odometry.tum, if any
  std::string truth;     // ground truth (TUM); empty: run.json's dataset/groundtruth.tum, if any
  std::string map;       // map (.ply / .pcd); empty: folder/map.ply, map.pcd, or run.json's prior map
  std::string world;     // true world (world.yaml); empty: beside the truth, if any
  std::size_t map_points = report::ReportOptions{}.map_point_budget;  // most map points drawn
};

int RunReport(const ReportCliOptions& o) {
  try {
    report::ReportOptions options;
    options.folder = o.folder;
    options.estimate_file = o.estimate;
    options.odometry_file = o.odometry;
    options.truth_file = o.truth;
    options.map_file = o.map;
    options.map_point_budget = o.map_points;
    const report::ReportResult result = WriteFolderReport(options, o.world);
    const report::ReportCounts& c = result.counts;
    std::cout << "trajectory: " << c.estimate_poses << " poses";
    if (c.truth_pairs > 0) std::cout << ", " << c.truth_pairs << " associated with the truth";
    std::cout << "\nplots: " << c.plots << " of " << c.plot_rows << " rows\n";
    if (c.map.total > 0) {
      std::cout << "map: " << c.map.shown << " of " << c.map.total << " points shown"
                << (c.map.error ? ", coloured by error against the true world" : "") << '\n';
    }
    if (c.loop_closures > 0) std::cout << "loop closures: " << c.loop_closures << '\n';
    std::cout << "wrote " << result.file.string() << '\n';
    return 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddReportCommand(CLI::App* app) {
  auto options = std::make_shared<ReportCliOptions>();
  CLI::App* cmd = app->add_subcommand(
      "report", "Build RUN_DIR/report.html from a run's outputs (or any folder with a TUM trajectory and a map)");
  cmd->add_option("RUN_DIR", options->folder, "Run folder (unimap run / localize / demo output)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--estimate", options->estimate, "Trajectory to show (TUM; default RUN_DIR/trajectory.tum)");
  cmd->add_option("--odometry", options->odometry,
                  "Second trajectory drawn beside it (TUM; default RUN_DIR/trajectory_odometry.tum if present)");
  cmd->add_option("--truth", options->truth,
                  "Ground truth (TUM; default groundtruth.tum of the dataset named in run.json, if present)");
  cmd->add_option("--map", options->map,
                  "Map (.ply or .pcd; default RUN_DIR/map.ply, map.pcd, or the prior map named in run.json)");
  cmd->add_option("--world", options->world,
                  "True world of simulated data (world.yaml; default: world.yaml beside the truth, if present)");
  cmd->add_option("--map-points", options->map_points, "Most map points drawn (every k-th point beyond)")
      ->capture_default_str()
      ->check(CLI::Range(static_cast<std::size_t>(1000), static_cast<std::size_t>(20000000)));
  cmd->callback([options]() {
    const int code = RunReport(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
