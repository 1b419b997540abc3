#pragma once
// The options that say how to read a recording (KITTI, CARMEN, ROS 1 and
// ROS 2 bags), shared by `unimap convert` and by `run` / `localize`, which
// read a recording given as --data directly (converted as it is read).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "RunOutputs.hpp"
#include "io/DatasetConversion.hpp"
#include "io/DatasetReader.hpp"

namespace unimap::cli {

struct RecordingOptions {
  io::ConversionOptions conversion;      // per-format options (input and output set by the command)
  std::string format;                    // kitti | carmen | rosbag | ros2 ("" = detected: run, localize)
  std::string carmen_odometry = "auto";  // auto | odom | flaser
  double carmen_fov_deg = 180.0;         // FLASER beams span
  std::string angle_unit;                // angle topic's number: deg | rad; "" = not given
  std::vector<CLI::Option*> added;       // the options AddRecordingOptions added (to tell whether any was given)

  // conversion with the string choices above resolved into its fields.
  io::ConversionOptions Resolved() const;
  // The first of `added` given on the command line, or nullptr.
  const CLI::Option* FirstGiven() const;
};

// Adds --payload, --reorder-window-s and every per-format option of
// `unimap convert` (KITTI side files, CARMEN, bag topics and angles) to cmd.
void AddRecordingOptions(CLI::App* cmd, RecordingOptions* options);

// A dataset to read: `data` as a dataset folder, or, when it is a recording
// (io::DetectRawInput; `recording.format` overrides the detected format), read
// directly through its conversion. A recording option given with a dataset
// folder is an InputError (it would be ignored).
struct OpenedData {
  std::unique_ptr<io::DatasetReader> reader;
  std::string recording_format;  // "" for a dataset folder
};
OpenedData OpenData(const std::string& data, const RecordingOptions& recording);

// After a run of a recording read directly: writes the ground truth it held
// to outputs->out_dir/groundtruth.tum and makes it outputs->truth_file (when
// there was any), and adds run.json's "recording" to outputs->extras: the
// format, the conversion's report (counts, skips, notes; "complete": false
// when the run stopped before the recording's end) and the events dropped
// for arriving late. Prints the report's skips and notes. Nothing for a
// dataset folder.
void FinishRecording(OpenedData& data, RunOutputsInput* outputs);

}  // namespace unimap::cli
