// `unimap run`: map a dataset (localisation, submaps, pose graph, loop
// closure); write the trajectories, the map, run.json and, with ground
// truth, the evaluation.
#include <memory>

#include "Commands.hpp"
#include "MappingRun.hpp"
#include "NumberChecks.hpp"
#include "RecordingOptions.hpp"
#include "SignalGuard.hpp"

namespace unimap::cli {

void AddRunCommand(CLI::App* app) {
  auto options = std::make_shared<MappingRunOptions>();
  CLI::App* cmd = app->add_subcommand("run", "Map a dataset with a platform (trajectory, map, evaluation)");
  cmd->add_option("--platform", options->platform_file, "Platform YAML")->required()->check(CLI::ExistingFile);
  cmd->add_option("--data", options->data_dir,
                  "Dataset folder (docs/dataset-format.md), or a recording read directly: a KITTI sequence or "
                  "folder of .bin/.pcd sweeps, a ROS 1 bag, a ROS 2 bag (folder or .db3), a CARMEN log; the "
                  "recording options are convert's")
      ->required()
      ->check(CLI::ExistingPath);
  cmd->add_option("--out", options->out_dir, "Output folder")->required();
  cmd->add_option("--max-duration-s", options->max_duration_s, "Process only this much data (s)")
      ->check(FinitePositive());
  cmd->add_flag("--force-payload", options->force_payload,
                "Run a dataset recorded for another payload than the platform's (an error otherwise)");
  cmd->add_option("--threads", options->threads, "Threads for particle weighting")->check(CLI::Range(1, 64));
  cmd->add_option("--seed", options->seed,
                  "Sampling seed of the particle filter (default 1); a run is deterministic for a seed and "
                  "thread count, so seeds show how much a result owes to chance");
  cmd->add_flag("--quiet", options->quiet, "No progress line");
  cmd->add_flag("--no-loop-closure", options->no_loop_closure, "Do not search for loop closures");
  cmd->add_flag("--trace", options->trace,
                "Also write trace.csv: per scan, how the localiser found its pose (points, particle weights, "
                "correction, standard deviations, velocity, IMU biases, the pseudo measurement)");
  cmd->add_flag("--plane-matching", options->plane_matching,
                "Odometry measures each scan point only across the map surface around it (a plane fitted to "
                "the surface voxels near it; points without one are not measured): for rotating 2D LiDARs, "
                "whose maps are stripes (docs/mapping.md)");
  cmd->add_flag("--no-line-gap-fill", options->no_line_gap_fill,
                "Line scans (rotating 2D LiDARs): do not fill the distance map's surface between consecutive "
                "lines; it then holds only the measured stripes (docs/mapping.md)");
  cmd->add_flag("--measure-all-line-points", options->measure_all_line_points,
                "Line scans (rotating 2D LiDARs): also measure the points farther than 1.5 voxels from the map "
                "at the predicted pose, which are left out by default (docs/mapping.md)");
  cmd->add_option("--motion", options->motion,
                  "Prediction between scans: auto (default: static for a platform whose body does not move, "
                  "else the IMU if the dataset has one, else its wheel odometry, else constant velocity), imu, "
                  "odometry (the dataset's odometry.csv), constant-velocity, or static (scans placed at the "
                  "start pose, not matched: a scanner on a fixed stand)")
      ->check(CLI::IsMember({"auto", "imu", "odometry", "constant-velocity", "static"}));
  cmd->add_option("--format", options->recording.format,
                  "The --data recording's format (default: detected; convert's --format)")
      ->check(CLI::IsMember({"kitti", "carmen", "rosbag", "ros2"}));
  AddRecordingOptions(cmd, &options->recording);
  cmd->callback([options]() {
    const SignalGuard guard;  // SIGINT / SIGTERM / SIGHUP: stop, write what was processed, exit 128 + signal
    const int code = SignalGuard::ExitCode(RunMappingToFolder(*options));
    if (code != 0) throw CLI::RuntimeError(code);
  });
}

}  // namespace unimap::cli
