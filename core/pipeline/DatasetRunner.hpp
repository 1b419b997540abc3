#pragma once
#include <atomic>
#include <functional>
#include <string>

#include "io/DatasetReader.hpp"
#include "io/TumTrajectory.hpp"
#include "pipeline/EventSink.hpp"

namespace unimap::pipeline {

// Progress of a run, reported about once per second of wall time.
struct RunProgress {
  std::size_t scans = 0;         // scans processed so far
  double data_time_s = 0.0;      // data time covered since the first event
  double data_duration_s = 0.0;  // expected total (metadata), 0 if unknown
  double wall_s = 0.0;           // processing time so far
};

struct RunOptions {
  double max_duration_s = 0.0;                          // stop after this much data time (0: all)
  const std::atomic<bool>* stop = nullptr;              // set (e.g. by SIGINT) to stop early
  std::function<void(const RunProgress&)> on_progress;  // optional
  std::function<void(const ScanPose&)> on_pose;         // optional: every pose as it is written
};

// What a run did and how fast.
struct RunSummary {
  std::size_t poses_written = 0;
  double data_duration_s = 0.0;  // time span of the data processed
  double processing_s = 0.0;     // wall time of the loop
  double realtime_factor = 0.0;  // data_duration_s / processing_s
  double peak_rss_mb = 0.0;      // process peak resident memory
  bool interrupted = false;      // stopped by RunOptions::stop
  std::string error;             // a reader error (truncated or malformed file) that ended the run early
};

// Feeds every event of a dataset to the sink (Localizer or Mapper) in time
// order and writes each scan pose (T_map_body) to the trajectory. Input
// errors inside the sink are counted skips; a reader error (truncated or malformed file)
// ends the run early, keeps what was processed and is reported in
// RunSummary::error.
RunSummary RunDataset(io::DatasetReader& reader, EventSink& sink, io::TumTrajectoryWriter& trajectory,
                      const RunOptions& options);

// Peak resident set size of this process (MiB) since it started or since
// the last ResetPeakRss() (Linux VmHWM; getrusage's lifetime peak where
// /proc is unavailable).
double PeakRssMb();
// Restarts the peak measurement at the current resident size (Linux
// /proc/self/clear_refs); returns false when the system does not allow it.
bool ResetPeakRss();

}  // namespace unimap::pipeline
