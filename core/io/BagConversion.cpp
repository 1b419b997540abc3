// WriteBagDataset (io/BagConversion.hpp): a bag reader's messages into a dataset.
#include "io/BagConversion.hpp"

#include <variant>
#include <vector>

#include "io/BagClockAligner.hpp"
#include "io/ReorderingDatasetWriter.hpp"

namespace unimap::io {
namespace {

// The payload the selected streams describe: 3D clouds or 2D lines, with a
// motor encoder or without (--payload overrides).
std::string DefaultPayload(const RosbagTopics& selected) {
  const bool cloud = !selected.cloud.empty();
  const bool motor = !selected.joint.empty() || !selected.angle.empty();
  if (cloud) return motor ? "rotating_3d" : "fixed_3d";
  return motor ? "rotating_2d" : "fixed_2d";
}

}  // namespace

ConversionReport WriteBagDataset(const ConversionOptions& options, const std::string& source, BagReader& reader) {
  const RosbagTopics& selected = reader.selected();
  ConversionReport report;
  // One scan stream per dataset: clouds if there are any, else laser lines.
  const std::string scan_topic = !selected.cloud.empty() ? selected.cloud : selected.laser;
  if (scan_topic.empty()) {
    report.notes.push_back("no PointCloud2 or LaserScan topic selected: the dataset has no scans");
  }
  const auto note = [&](const char* stream, const std::string& topic) {
    report.notes.push_back(std::string(stream) + ": " + (topic.empty() ? std::string("(none)") : topic));
  };
  note("cloud topic", selected.cloud);
  note("laser topic", selected.laser);
  note("imu topic", selected.imu);
  note("joint (encoder) topic", selected.joint);
  note("odometry topic", selected.odometry);
  note("groundtruth topic", selected.groundtruth);
  if (!selected.cloud.empty() && !selected.laser.empty()) {
    report.notes.push_back("both a cloud and a laser topic: writing " + selected.cloud +
                           "; use --cloud-topic none to write " + selected.laser + " instead");
  }

  DatasetMetadata metadata;
  metadata.source = source;
  metadata.payload = options.payload.empty() ? DefaultPayload(selected) : options.payload;
  report.payload = metadata.payload;
  ReorderingDatasetWriter writer(OpenDatasetSink(options, metadata), options.reorder_window_s, &report);
  bool time_convention_noted = false;
  const auto write = [&](RosbagMessage* message) {
    std::visit(
        [&](auto& data) {
          using T = std::decay_t<decltype(data)>;
          if constexpr (std::is_same_v<T, RawScan> || std::is_same_v<T, LineScan>) {
            if (message->topic != scan_topic) {
              ++report.skipped[message->topic + ": second scan topic (not converted)"];
              return;
            }
            if constexpr (std::is_same_v<T, RawScan>) {
              report.dropped_points += message->dropped_points;
              if (!time_convention_noted) {
                report.notes.push_back(message->topic + " point times: " + ToString(message->time_convention));
                time_convention_noted = true;
              }
            }
            writer.WriteScan(std::move(data));
          } else if constexpr (std::is_same_v<T, ImuSample>) {
            writer.WriteImu(data);
          } else if constexpr (std::is_same_v<T, EncoderSample>) {
            writer.WriteEncoder(data);
          } else if constexpr (std::is_same_v<T, OdometrySample>) {
            writer.WriteOdometry(data);
          } else {
            writer.WriteGroundTruth(data);
          }
        },
        message->data);
  };
  BagClockAligner clocks(options.clocks, &report.notes);
  std::vector<RosbagMessage> ready;
  while (std::optional<RosbagMessage> message = reader.Next()) {
    if (options.stop != nullptr && options.stop->load()) {
      report.interrupted = true;
      break;
    }
    clocks.Push(std::move(*message), &ready);
    for (RosbagMessage& m : ready) write(&m);
    ready.clear();
  }
  clocks.Finish(&ready);
  for (RosbagMessage& m : ready) write(&m);
  writer.Finish();
  for (const auto& [reason, count] : reader.stats().skipped) report.skipped[reason] += count;
  return report;
}

}  // namespace unimap::io
