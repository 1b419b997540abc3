#pragma once
// The mapping job shared by `unimap run` and `unimap demo`: map a dataset
// with a platform and write every output into a folder.
#include <cstdint>
#include <string>

#include "RecordingOptions.hpp"

namespace unimap::cli {

struct MappingRunOptions {
  std::string platform_file;             // platform YAML
  std::string data_dir;                  // dataset folder, or a recording read directly
  RecordingOptions recording;            // how to read a recording given as data_dir
  std::string out_dir;                   // output folder
  double max_duration_s = 0.0;           // 0: the whole dataset
  int threads = 1;                       // GPF threads
  std::uint64_t seed = 1;                // GPF sampling seed (matching::GpfOptions::seed)
  bool quiet = false;                    // no progress line
  bool no_loop_closure = false;          // map without loop-closure search
  bool no_line_gap_fill = false;         // line scans: the distance map holds the measured stripes only
  bool measure_all_line_points = false;  // line scans: also measure points far from the map at the
                                         // prediction (LocalizerOptions::max_predicted_distance_m 0)
  bool plane_matching = false;           // odometry matches points against neighbourhood planes only
                                         // (LocalizerOptions::UsePlaneMatching)
  bool trace = false;                    // write trace.csv (ScanDiagnostics of every pose)
  bool force_payload = false;            // run a dataset recorded for another payload (else an error)
  std::string motion = "auto";           // prediction source: auto (what the dataset holds), imu, odometry
                                         // (odometry.csv) or constant-velocity
};

// Runs the Mapper over the dataset and writes trajectory_odometry.tum
// (streamed), trajectory.tum and trajectory_kitti.txt (optimised), map.pcd,
// map.ply, map.bt, run.json and, with ground truth, metrics.json and the
// report. Returns the exit code (0, or 2 after a printed error).
int RunMappingToFolder(const MappingRunOptions& options);

}  // namespace unimap::cli
