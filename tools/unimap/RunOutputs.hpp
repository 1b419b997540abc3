#pragma once
// The outputs shared by `unimap run` and `unimap localize`: run.json, the
// console summary and, with ground truth, the evaluation.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "Json.hpp"
#include "pipeline/DatasetRunner.hpp"
#include "pipeline/Localizer.hpp"

namespace unimap::cli {

// Everything a finished run reports.
struct RunOutputsInput {
  std::filesystem::path out_dir;     // holds trajectory.tum (written by the run); gets run.json etc.
  std::string platform_file;         // run.json "platform"
  std::string payload;               // run.json "payload" (plugin name)
  std::string data_dir;              // run.json "dataset"; its groundtruth.tum is the truth
  std::size_t gpf_threads = 1;       // run.json "gpf_threads"
  std::uint64_t gpf_seed = 1;        // run.json "gpf_seed"
  std::string motion;                // run.json "motion": the prediction used (empty: not reported)
  std::string motion_reason;         // run.json "motion_reason": why
  pipeline::RunSummary summary;      // what the run did and how fast
  pipeline::LocalizerStats stats;    // the localiser's counts (run.json "localizer")
  bool has_groundtruth = false;      // the dataset has groundtruth.tum (or truth_file)
  std::filesystem::path truth_file;  // the truth when not data_dir/groundtruth.tum (a recording read directly)
  // Estimate and truth share one frame (localisation in a prior map whose
  // frame is the truth's): run.json also gets the unaligned errors
  // position_rmse_m, rotation_rmse_deg, position_max_error_m,
  // rotation_max_error_deg and error_poses (null when nothing associates).
  bool world_frame_errors = false;
  std::string trajectory_file = "trajectory.tum";  // in out_dir: the trajectory evaluated (metrics.json)
  std::string map_file;       // when not empty (in out_dir) and the dataset has world.yaml: map error
  std::string odometry_file;  // when not empty (in out_dir): also evaluated, summary in run.json "odometry"
  std::vector<std::pair<std::string, Json>> extras;  // command-specific objects for run.json (key, object)

  // truth_file, or data_dir/groundtruth.tum.
  std::filesystem::path TruthFile() const {
    return truth_file.empty() ? std::filesystem::path(data_dir) / "groundtruth.tum" : truth_file;
  }
};

// Unaligned errors of an estimate against the truth in the same frame.
struct WorldFrameErrors {
  double position_rmse_m = 0.0;         // sqrt(mean |p_est - p_true|^2)
  double rotation_rmse_deg = 0.0;       // sqrt(mean theta^2), theta = |log(q_est^-1 q_true)|
  double position_max_error_m = 0.0;    // max |p_est - p_true|
  double rotation_max_error_deg = 0.0;  // max theta
  std::size_t poses = 0;                // estimate poses associated with the truth (0: the rest is undefined)
};

// Associates estimate and truth by time (eval::AssociateTrajectories,
// default tolerance) and computes the errors without any alignment.
WorldFrameErrors ComputeWorldFrameErrors(const std::vector<StampedPose>& estimate,
                                         const std::vector<StampedPose>& truth);

// The localiser's counts as run.json's "localizer" object.
Json LocalizerStatsJson(const pipeline::LocalizerStats& stats);
// Stage times as run.json's "stages" object (seconds, and each stage's share
// of processing_s), printed as one line when print is set.
Json StageTimesJson(const pipeline::StageTimes& times, double processing_s, bool print);

// The progress line on stderr: scans, scans/s, real-time factor, ETA.
void PrintRunProgress(const pipeline::RunProgress& progress);

// The fields every command fills the same way.
RunOutputsInput MakeRunOutputsInput(const std::filesystem::path& out_dir, const std::string& platform_file,
                                    const std::string& payload, const std::string& data_dir, int gpf_threads,
                                    const pipeline::RunSummary& summary, const pipeline::LocalizerStats& stats,
                                    bool has_groundtruth);

// Runs the sink (Localizer or Mapper) over the dataset, streaming its poses
// into out_dir/trajectory_file (creating out_dir), with a progress line
// unless quiet; a SignalGuard's signal stops the run and keeps what was processed. With
// trace, every pose's ScanDiagnostics also go to out_dir/trace.csv.
pipeline::RunSummary RunSinkToFolder(io::DatasetReader& reader, pipeline::EventSink& sink,
                                     const std::filesystem::path& out_dir, const std::string& trajectory_file,
                                     double max_duration_s, bool quiet, bool trace = false);

// Writes out_dir/run.json, prints the summary and skip messages, and with
// ground truth (and at least two poses) evaluates trajectory.tum against it
// (metrics.json, figures, report.html) and prints the metrics. Returns the
// exit code: 2 when the run ended on a reader error (printed), else 0.
// Throws unimap::Error when a file cannot be read or written.
int WriteRunOutputs(const RunOutputsInput& input);

}  // namespace unimap::cli
