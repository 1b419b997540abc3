#include "pipeline/DatasetRunner.hpp"

#include <sys/resource.h>

#include <chrono>
#include <fstream>
#include <string>
#include <variant>

#include "unimap/Errors.hpp"

namespace unimap::pipeline {
namespace {

double EventTime(const io::DatasetEvent& event) {
  if (const auto* imu = std::get_if<ImuSample>(&event)) return imu->time_s;
  if (const auto* enc = std::get_if<EncoderSample>(&event)) return enc->time_s;
  if (const auto* odom = std::get_if<OdometrySample>(&event)) return odom->time_s;
  return io::ScanEndTime(std::get<io::ScanRecord>(event));
}

void WritePoses(EventSink& localizer, io::TumTrajectoryWriter& trajectory, const RunOptions& options,
                RunSummary* summary) {
  for (const ScanPose& pose : localizer.TakePoses()) {
    trajectory.Write({pose.time_s, pose.T_map_body});
    if (options.on_pose) options.on_pose(pose);
    ++summary->poses_written;
  }
}

}  // namespace

double PeakRssMb() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // "VmHWM:  123456 kB"
  }
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

bool ResetPeakRss() {
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";  // resets the peak resident set size (VmHWM)
  clear.flush();
  return static_cast<bool>(clear);
}

RunSummary RunDataset(io::DatasetReader& reader, EventSink& localizer, io::TumTrajectoryWriter& trajectory,
                      const RunOptions& options) {
  using Clock = std::chrono::steady_clock;
  RunSummary summary;
  const auto start = Clock::now();
  auto last_report = start;
  double first_time = 0.0, last_time = 0.0;
  bool any = false;
  try {
    while (std::optional<io::DatasetEvent> event = reader.NextEvent()) {
      const double t = EventTime(*event);
      if (!any) first_time = t;
      any = true;
      if (options.max_duration_s > 0.0 && t - first_time > options.max_duration_s) break;
      if (options.stop != nullptr && options.stop->load()) {
        summary.interrupted = true;
        break;
      }
      last_time = std::max(last_time, t);
      if (auto* imu = std::get_if<ImuSample>(&*event)) {
        localizer.AddImu(*imu);
      } else if (auto* enc = std::get_if<EncoderSample>(&*event)) {
        localizer.AddEncoder(*enc);
      } else if (auto* scan = std::get_if<io::ScanRecord>(&*event)) {
        localizer.AddScan(std::move(*scan));
      } else if (auto* odometry = std::get_if<OdometrySample>(&*event)) {
        localizer.AddOdometry(*odometry);
      }
      WritePoses(localizer, trajectory, options, &summary);
      const auto now = Clock::now();
      if (options.on_progress && now - last_report > std::chrono::seconds(1)) {
        last_report = now;
        options.on_progress({localizer.ScansReceived(), last_time - first_time, reader.metadata().duration_s,
                             std::chrono::duration<double>(now - start).count()});
      }
    }
  } catch (const Error& e) {
    summary.error = e.what();
  }
  localizer.Finish();
  WritePoses(localizer, trajectory, options, &summary);
  trajectory.Close();
  summary.processing_s = std::chrono::duration<double>(Clock::now() - start).count();
  summary.data_duration_s = any ? last_time - first_time : 0.0;
  summary.realtime_factor = summary.processing_s > 0.0 ? summary.data_duration_s / summary.processing_s : 0.0;
  summary.peak_rss_mb = PeakRssMb();
  return summary;
}

}  // namespace unimap::pipeline
