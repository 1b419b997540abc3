#pragma once
// Subcommands of the `unimap` command line; each registers itself on the app.
#include <CLI/CLI.hpp>

namespace unimap::cli {

// `unimap plugins`: the payload plugins found, with versions, paths and defaults.
void AddPluginsCommand(CLI::App* app);
// `unimap config --platform FILE`: effective parameters and where each came from.
void AddConfigCommand(CLI::App* app);
// `unimap simulate`: writes a simulated dataset for a scenario and payload.
void AddSimulateCommand(CLI::App* app);
// `unimap evaluate`: trajectory metrics, plots and report against ground truth.
void AddEvaluateCommand(CLI::App* app);
// `unimap convert`: KITTI, CARMEN and ROS 1 bag data into the dataset format.
void AddConvertCommand(CLI::App* app);
// `unimap run`: localise a dataset (odometry mode) and evaluate it.
void AddRunCommand(CLI::App* app);
// `unimap localize`: localise a dataset in a fixed prior map (.bt or .pcd) and evaluate it.
void AddLocalizeCommand(CLI::App* app);
// `unimap bench`: speed figures written to docs/benchmarks.md.
void AddBenchCommand(CLI::App* app);
// `unimap report RUN_DIR`: the run folder's report.html, rebuilt from its outputs.
void AddReportCommand(CLI::App* app);
// `unimap calibrate`: a rig's LiDAR extrinsic from its own map; writes a platform file.
void AddCalibrateCommand(CLI::App* app);
// `unimap demo`: simulate the paper's tunnel, map it, compare with the paper.
void AddDemoCommand(CLI::App* app);

}  // namespace unimap::cli
