#pragma once
// The returns `unimap calibrate` works on: every scan of a dataset placed by
// the payload's own model (plugin), with the body's poses from a trajectory
// or standing still.
#include <cstddef>
#include <string>
#include <vector>

#include "calibration/ExtrinsicCalibrator.hpp"
#include "io/DatasetReader.hpp"
#include "unimap/PayloadPlugin.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::cli {

struct CalibrationInput {
  std::vector<calibration::CalibrationReturn> returns;
  std::size_t scans = 0;            // scans read
  std::size_t scans_used = 0;       // ... placed (their returns are in `returns`)
  std::size_t scans_outside = 0;    // ... not placed: outside the encoder's or the trajectory's span
  std::size_t encoder_samples = 0;  // encoder samples read
  std::string first_skip;           // why the first scan not placed was not (empty: none)
};

// Reads the dataset's scans (those ending within max_duration_s of the first;
// <= 0: all) and encoder samples, and places each scan's returns once the
// encoder covers it (only the returns are kept, 48 bytes each): the plugin
// deskews it as for a body at rest, which gives each return in the body
// frame at its firing time t; its LiDAR-frame position is
// T_body_lidar(t)^-1 times that and T_world_lidar = T_world_body(t)
// T_body_lidar(t), with T_world_body from `trajectory` (interpolated; scans
// outside its span are skipped and counted) or the identity when it is
// empty. Throws InputError for a malformed dataset.
CalibrationInput ReadCalibrationInput(io::DatasetReader& reader, const PayloadPlugin& plugin,
                                      const std::vector<StampedPose>& trajectory, double max_duration_s);

}  // namespace unimap::cli
