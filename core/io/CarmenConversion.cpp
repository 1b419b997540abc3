// ConvertCarmen (io/DatasetConversion.hpp): a CARMEN log into a dataset.
#include <variant>

#include "io/DatasetConversion.hpp"
#include "io/ReorderingDatasetWriter.hpp"

namespace unimap::io {

ConversionReport ConvertCarmen(const ConversionOptions& options) {
  ConversionReport report;
  bool odom_lines = options.carmen_odometry == CarmenOdometrySource::kOdomLines;
  if (options.carmen_odometry == CarmenOdometrySource::kAuto) {
    odom_lines = CarmenReader::HasOdometryLines(options.input);
    report.notes.push_back(odom_lines ? "odometry from ODOM lines"
                                      : "no ODOM lines: odometry from the FLASER odom_x odom_y odom_theta fields");
  }
  CarmenReader reader(options.input, options.carmen);

  DatasetMetadata metadata;
  metadata.source = "carmen";
  // A fixed planar laser: the fixed_2d payload (--payload overrides it).
  metadata.payload = options.payload.empty() ? "fixed_2d" : options.payload;
  report.payload = metadata.payload;
  ReorderingDatasetWriter writer(OpenDatasetSink(options, metadata), options.reorder_window_s, &report);

  while (std::optional<CarmenMessage> message = reader.Next()) {
    if (options.stop != nullptr && options.stop->load()) {
      report.interrupted = true;
      break;
    }
    if (auto* laser = std::get_if<CarmenLaser>(&*message)) {
      if (!odom_lines) writer.WriteOdometry(laser->odometry);
      writer.WriteScan(std::move(laser->scan));
    } else {
      const auto& odometry = std::get<CarmenOdometry>(*message);
      if (odom_lines) {
        writer.WriteOdometry(odometry.odometry);
      } else {
        ++report.skipped["ODOM lines (odometry taken from FLASER fields)"];
      }
    }
  }
  writer.Finish();

  const CarmenReaderStats& stats = reader.stats();
  for (const auto& [type, count] : stats.other_messages) report.skipped[type + " lines (not converted)"] += count;
  for (const auto& [reason, count] : stats.skipped) report.skipped[reason] += count;
  for (const CarmenSkippedLine& line : stats.skipped_lines) {
    report.notes.push_back(options.input.string() + ":" + std::to_string(line.line) + ": skipped: " + line.reason);
  }
  if (stats.truncated_input) {
    report.notes.push_back(options.input.string() +
                           ": compressed data ends early (file truncated); converted what was there");
  }
  return report;
}

}  // namespace unimap::io
