// `unimap evaluate`: trajectory metrics, plots and an HTML report against
// ground truth and, with a map and the simulated world, the map's accuracy
// (definitions in docs/evaluation.md).
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "Commands.hpp"
#include "FolderReport.hpp"
#include "Json.hpp"
#include "MapEvaluation.hpp"
#include "MapQualityMetrics.hpp"
#include "TextTable.hpp"
#include "eval/AtomicFile.hpp"
#include "eval/EvaluationReport.hpp"
#include "eval/MetricRows.hpp"
#include "eval/TrajectoryEvaluation.hpp"
#include "io/TumTrajectory.hpp"
#include "unimap/Errors.hpp"

namespace unimap::cli {
namespace {

struct EvaluateOptions {
  std::string estimate_file;     // estimated trajectory, TUM
  std::string truth_file;        // ground truth, TUM
  std::string out_dir;           // output folder; empty = the estimate's folder
  std::string map_file;          // map to score (.pcd or .ply, estimate frame); empty = none
  std::string world_file;        // true world (world.yaml); empty = world.yaml beside the truth, if any
  double max_time_diff_s = 0.1;  // association tolerance
  double segment_m = 10.0;       // RPE segment length
  std::string anchor = "yaw";    // start anchoring: "yaw" (position + heading) or "full" (whole first pose)
};

// Reads one TUM file; a missing file is an InputError naming it.
std::vector<StampedPose> ReadTrajectory(const std::string& file, const char* role) {
  if (!std::filesystem::is_regular_file(file)) {
    throw InputError(std::string(role) + " " + file + ": no such file");
  }
  return io::ReadTumTrajectory(file);
}

// Throws InputError unless value is a positive finite number.
void RequirePositive(const char* option, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(std::string(option) + " must be a positive number (got " + std::to_string(value) + ")");
  }
}

// Without a trajectory: the map's GT-free quality, printed and written to
// OUT/metrics.json (OUT: --out, else the map's folder).
int EvaluateMapOnly(const EvaluateOptions& options) {
  const std::vector<Eigen::Vector3f> points = LoadMapPoints(options.map_file);
  const std::vector<eval::ExtraMetric> metrics = MapMetricsWithoutTruth(points);
  const std::filesystem::path out_dir = options.out_dir.empty()
                                            ? std::filesystem::absolute(options.map_file).parent_path()
                                            : std::filesystem::path(options.out_dir);
  std::cout << "map:      " << options.map_file << "  (" << points.size() << " points; no ground truth)\n\n";
  TextTable table({"metric", "value", "meaning"});
  Json json = Json::object();
  for (const eval::ExtraMetric& m : metrics) {
    table.AddRow({m.row.key, m.row.value, m.row.meaning});
    json[m.row.key] = m.value;
  }
  table.Print(std::cout);
  std::filesystem::create_directories(out_dir);
  eval::WriteFileAtomically(out_dir / "metrics.json", JsonText(json) + "\n");
  std::cout << "\nwrote:\n  " << (out_dir / "metrics.json").string() << '\n';
  return 0;
}

int RunEvaluate(const EvaluateOptions& options) {
  try {
    if (options.estimate_file.empty() != options.truth_file.empty()) {
      throw InputError(std::string(options.truth_file.empty() ? "--estimate" : "--truth") + " needs " +
                       (options.truth_file.empty() ? "--truth" : "--estimate") +
                       " (or give --map alone for the map's quality without ground truth)");
    }
    if (options.truth_file.empty()) {
      if (options.map_file.empty()) throw InputError("nothing to evaluate: give --estimate and --truth, or --map");
      return EvaluateMapOnly(options);
    }
    RequirePositive("--max-time-diff-s", options.max_time_diff_s);
    RequirePositive("--segment-m", options.segment_m);
    const std::vector<StampedPose> estimate = ReadTrajectory(options.estimate_file, "estimate");
    const std::vector<StampedPose> truth = ReadTrajectory(options.truth_file, "truth");
    eval::EvaluationOptions eval_options;
    eval_options.association.max_time_diff_s = options.max_time_diff_s;
    eval_options.segment_m = options.segment_m;
    eval_options.anchor = options.anchor == "full" ? eval::Anchor::kFullPose : eval::Anchor::kYawPosition;
    eval::TrajectoryEvaluation evaluation;
    try {
      evaluation = eval::EvaluateTrajectory(estimate, truth, eval_options);
    } catch (const InputError& e) {
      throw InputError("estimate " + options.estimate_file + " vs truth " + options.truth_file + ": " + e.what());
    }
    // Map accuracy: unaligned (the estimate's map frame taken as the world
    // frame) and after the trajectory's ATE alignment (estimate -> truth).
    std::optional<MapEvaluation> map_evaluation;
    const std::optional<std::filesystem::path> world_file = ResolveWorldFile(options.world_file, options.truth_file);
    if (!options.map_file.empty() && world_file) {
      map_evaluation = EvaluateMapFile(options.map_file, *world_file, evaluation.errors.alignment.T_target_source,
                                       evaluation.errors.T_true_est_anchor);
    } else if (!options.map_file.empty()) {
      std::cerr << "note: no world file (--world, or world.yaml beside " << options.truth_file
                << "): map error not computed\n";
    } else if (!options.world_file.empty()) {
      std::cerr << "note: --world without --map: map error not computed\n";
    }
    const std::filesystem::path out_dir = options.out_dir.empty()
                                              ? std::filesystem::absolute(options.estimate_file).parent_path()
                                              : std::filesystem::path(options.out_dir);

    std::cout << "estimate: " << options.estimate_file << "  (" << estimate.size() << " poses)\n"
              << "truth:    " << options.truth_file << "  (" << truth.size() << " poses)\n";
    if (map_evaluation) {
      std::cout << "map:      " << options.map_file << "  (" << map_evaluation->unaligned.points << " points)\n"
                << "world:    " << world_file->string() << '\n';
    }
    std::cout << '\n';
    TextTable table({"metric", "value", "meaning"});
    for (const eval::MetricRow& row : eval::DescribeMetrics(evaluation.metrics)) {
      table.AddRow({row.key, row.value, row.meaning});
    }
    eval::ReportExtras map_extras = map_evaluation ? MapReportExtras(*map_evaluation) : eval::ReportExtras{};
    if (!options.map_file.empty()) {  // its quality without the truth, with or without a world
      for (eval::ExtraMetric& m : MapMetricsWithoutTruth(LoadMapPoints(options.map_file))) {
        map_extras.metrics.push_back(std::move(m));
      }
    }
    for (const eval::ExtraMetric& m : map_extras.metrics) table.AddRow({m.row.key, m.row.value, m.row.meaning});
    table.Print(std::cout);
    const std::vector<std::filesystem::path> written = eval::WriteEvaluationReport(evaluation, out_dir, map_extras);
    report::ReportOptions report_options;
    report_options.folder = out_dir;
    report_options.estimate_file = options.estimate_file;
    report_options.truth_file = options.truth_file;
    report_options.map_file = options.map_file;
    report_options.evaluation = eval_options;
    const report::ReportResult report = WriteFolderReport(report_options, world_file ? world_file->string() : "");
    std::cout << "\nwrote:\n";
    for (const auto& file : written) std::cout << "  " << file.string() << '\n';
    std::cout << "  " << report.file.string() << '\n';
    return 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddEvaluateCommand(CLI::App* app) {
  auto options = std::make_shared<EvaluateOptions>();
  CLI::App* cmd = app->add_subcommand(
      "evaluate",
      "Compare an estimated trajectory with ground truth (and a map with the simulated world): metrics.json, "
      "PNG plots, report.html (interactive: unimap report)");
  cmd->add_option("--estimate", options->estimate_file,
                  "Estimated trajectory (TUM: t x y z qx qy qz qw); with --truth");
  cmd->add_option("--truth", options->truth_file,
                  "Ground-truth trajectory (TUM); without it, --map alone is scored "
                  "without ground truth (mean map entropy, plane variance)");
  cmd->add_option("--out", options->out_dir, "Output folder (default: the estimate's folder)");
  cmd->add_option("--map", options->map_file,
                  "Map to score against the world (.pcd or .ply, in the estimate's frame): map_error_* metrics");
  cmd->add_option("--world", options->world_file,
                  "True world of simulated data (world.yaml; default: world.yaml beside --truth, if present)");
  cmd->add_option("--max-time-diff-s", options->max_time_diff_s,
                  "Largest time from an estimate pose to each bracketing truth sample")
      ->capture_default_str();
  cmd->add_option("--anchor", options->anchor,
                  "Start anchoring: yaw = first position and heading (gravity-aligned estimates, default), "
                  "full = the whole first pose (estimates in an arbitrary frame)")
      ->check(CLI::IsMember({"yaw", "full"}));
  cmd->add_option("--segment-m", options->segment_m, "Travelled distance per RPE segment")->capture_default_str();
  cmd->callback([options]() {
    const int code = RunEvaluate(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
