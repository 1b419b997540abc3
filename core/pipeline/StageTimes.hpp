#pragma once
#include <chrono>

namespace unimap::pipeline {

// Where a run's processing time went, per stage (wall seconds, summed over
// the run; run.json "stages", `unimap bench`). Map-thread stages are
// measured on that thread; offline runs wait for it, so the stages add up to
// about the processing time.
struct StageTimes {
  double deskew_s = 0.0;        // line-scan conversion and the plugin's deskew
  double downsample_s = 0.0;    // voxel filters: scans before matching, 3D scans before insertion
  double match_s = 0.0;         // particle filter and refinement (without its downsampling)
  double eskf_s = 0.0;          // IMU propagation, motion prediction, pose updates
  double map_surface_s = 0.0;   // returns into the map's surface (elements / occupancy)
  double map_distance_s = 0.0;  // distance-field updates
  double map_export_s = 0.0;    // publishing fields to the matcher
  double loop_search_s = 0.0;   // loop-closure candidates and matching
  double optimization_s = 0.0;  // pose-graph optimisation (background solver time)
  double outputs_s = 0.0;       // trajectories, map files, evaluation and report
};

// Adds the time from its construction to its destruction to *total_s.
class StageTimer {
 public:
  explicit StageTimer(double* total_s) : total_s_(total_s), start_(std::chrono::steady_clock::now()) {}
  ~StageTimer() { *total_s_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  double* total_s_;
  std::chrono::steady_clock::time_point start_;
};

}  // namespace unimap::pipeline
