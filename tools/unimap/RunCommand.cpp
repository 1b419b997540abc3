// `unimap run`: localise a dataset (odometry mode), write the trajectory,
// run.json and, with ground truth, the evaluation.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>

#include "Commands.hpp"
#include "JsonObject.hpp"
#include "eval/AtomicFile.hpp"
#include "eval/EvaluationReport.hpp"
#include "eval/MetricRows.hpp"
#include "eval/TrajectoryEvaluation.hpp"
#include "io/DatasetReader.hpp"
#include "io/TumTrajectory.hpp"
#include "pipeline/DatasetRunner.hpp"
#include "pipeline/Localizer.hpp"
#include "unimap/CoreParameters.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Platform.hpp"

namespace unimap::cli {
namespace {

std::atomic<bool> g_stop{false};
extern "C" void OnSigint(int /*signal*/) { g_stop.store(true); }

struct RunCliOptions {
  std::string platform_file;    // platform YAML
  std::string data_dir;         // dataset folder
  std::string out_dir;          // output folder
  double max_duration_s = 0.0;  // 0: the whole dataset
  int threads = 1;              // GPF threads
  bool quiet = false;           // no progress line
};

JsonObject StatsJson(const pipeline::LocalizerStats& s) {
  JsonObject o;
  o.Add("imu_samples", s.imu_samples);
  o.Add("imu_out_of_order", s.imu_out_of_order);
  o.Add("imu_gaps", s.imu_gaps);
  o.Add("encoder_rejected", s.encoder_rejected);
  o.Add("scans_matched", s.scans_matched);
  o.Add("scans_unmatched", s.scans_unmatched);
  o.Add("scans_bad_input", s.scans_bad_input);
  o.Add("scans_no_encoder", s.scans_no_encoder);
  o.Add("scans_out_of_order", s.scans_out_of_order);
  o.Add("beams_dropped", s.beams_dropped);
  o.Add("map_insertions", s.map_insertions);
  o.Add("messages", s.messages);
  return o;
}

void PrintProgress(const pipeline::RunProgress& p) {
  const double rtf = p.wall_s > 0.0 ? p.data_time_s / p.wall_s : 0.0;
  std::fprintf(stderr, "\r%zu scans | %.0f scans/s | %.1fx real time", p.scans,
               p.wall_s > 0.0 ? static_cast<double>(p.scans) / p.wall_s : 0.0, rtf);
  if (p.data_duration_s > 0.0 && rtf > 0.0) {
    std::fprintf(stderr, " | %.0f%% | ETA %.0f s   ", 100.0 * p.data_time_s / p.data_duration_s,
                 std::max(0.0, (p.data_duration_s - p.data_time_s) / rtf));
  }
  std::fflush(stderr);
}

int RunRun(const RunCliOptions& options) {
  try {
    const Platform platform = LoadPlatform(options.platform_file);
    pipeline::LocalizerOptions localizer_options =
        pipeline::LocalizerOptions::FromPlatform(CoreParameters::FromMap(platform.parameters));
    localizer_options.gpf.threads = options.threads;
    io::DatasetReader reader(options.data_dir);
    if (!reader.metadata().payload.empty() && reader.metadata().payload != platform.plugin.plugin->Name()) {
      std::cerr << "warning: dataset was recorded for payload '" << reader.metadata().payload
                << "', platform uses '" << platform.plugin.plugin->Name() << "'\n";
    }
    const std::filesystem::path out(options.out_dir);
    std::filesystem::create_directories(out);
    pipeline::Localizer localizer(localizer_options, platform.plugin.plugin);
    io::TumTrajectoryWriter trajectory(out / "trajectory.tum");
    pipeline::RunOptions run_options;
    run_options.max_duration_s = options.max_duration_s;
    run_options.stop = &g_stop;
    if (!options.quiet) run_options.on_progress = PrintProgress;
    const auto previous = std::signal(SIGINT, OnSigint);
    const pipeline::RunSummary summary = pipeline::RunDataset(reader, localizer, trajectory, run_options);
    std::signal(SIGINT, previous);
    if (!options.quiet) std::fprintf(stderr, "\n");

    JsonObject run;
    run.Add("realtime_factor", summary.realtime_factor);
    run.Add("processing_s", summary.processing_s);
    run.Add("data_duration_s", summary.data_duration_s);
    run.Add("scans", localizer.stats().scans);
    run.Add("poses", summary.poses_written);
    run.Add("peak_rss_mb", summary.peak_rss_mb);
    run.Add("interrupted", summary.interrupted);
    run.Add("error", summary.error);
    run.Add("platform", options.platform_file);
    run.Add("payload", platform.plugin.plugin->Name());
    run.Add("dataset", options.data_dir);
    run.Add("gpf_threads", static_cast<std::size_t>(options.threads));
    run.Add("localizer", StatsJson(localizer.stats()));
    eval::WriteFileAtomically(out / "run.json", run.ToString() + "\n");

    std::cout << "scans " << localizer.stats().scans << " (matched " << localizer.stats().scans_matched
              << "), data " << summary.data_duration_s << " s in " << summary.processing_s << " s: "
              << summary.realtime_factor << "x real time, peak RSS " << summary.peak_rss_mb << " MiB\n";
    for (const auto& message : localizer.stats().messages) std::cout << "  skipped: " << message << '\n';
    if (reader.has_groundtruth() && summary.poses_written >= 2) {
      const auto truth = io::ReadTumTrajectory(std::filesystem::path(options.data_dir) / "groundtruth.tum");
      const auto estimate = io::ReadTumTrajectory(out / "trajectory.tum");
      const eval::TrajectoryEvaluation evaluation = eval::EvaluateTrajectory(estimate, truth, {});
      eval::WriteEvaluationReport(evaluation, {(out / "trajectory.tum").string(),
                                               (std::filesystem::path(options.data_dir) / "groundtruth.tum").string()},
                                  out);
      for (const eval::MetricRow& row : eval::DescribeMetrics(evaluation.metrics)) {
        std::cout << "  " << row.key << " = " << row.value << '\n';
      }
    }
    std::cout << "wrote " << (out / "trajectory.tum").string() << ", " << (out / "run.json").string() << '\n';
    if (!summary.error.empty()) {
      std::cerr << "error: " << options.data_dir << ": " << summary.error << " (outputs hold what was processed)\n";
      return 2;
    }
    return 0;
  } catch (const Error& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}

}  // namespace

void AddRunCommand(CLI::App* app) {
  auto options = std::make_shared<RunCliOptions>();
  CLI::App* cmd = app->add_subcommand("run", "Localise a dataset with a platform (odometry mode) and evaluate it");
  cmd->add_option("--platform", options->platform_file, "Platform YAML")->required()->check(CLI::ExistingFile);
  cmd->add_option("--data", options->data_dir, "Dataset folder (docs/dataset-format.md)")
      ->required()
      ->check(CLI::ExistingDirectory);
  cmd->add_option("--out", options->out_dir, "Output folder")->required();
  cmd->add_option("--max-duration-s", options->max_duration_s, "Process only this much data (s)");
  cmd->add_option("--threads", options->threads, "Threads for particle weighting")->check(CLI::Range(1, 64));
  cmd->add_flag("--quiet", options->quiet, "No progress line");
  cmd->callback([options]() {
    const int code = RunRun(*options);
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
