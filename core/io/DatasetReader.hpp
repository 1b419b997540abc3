#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <variant>

#include "io/DatasetConversion.hpp"
#include "io/DatasetLimits.hpp"
#include "io/DatasetMetadata.hpp"
#include "io/ScanRecord.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::io {

// One time-stamped item of a dataset.
using DatasetEvent = std::variant<ImuSample, EncoderSample, OdometrySample, ScanRecord>;

// An event's place in time order: a scan's end time, the others' time_s.
double EventTime(const DatasetEvent& event);

// Streams a dataset folder without holding it in memory: buffered reads, at
// most one decoded item held per stream. A stream whose file is absent is
// empty; ".partial" files are ignored. Per-stream readers return
// std::nullopt at the end of a stream; a malformed or truncated record, or
// time going backwards within a file, throws InputError naming the file and
// the record ("file:line: ..." for text, "scans.bin: record k (byte o): ..."
// for scans, k counted from 1).
class DatasetReader {
 public:
  // Reads metadata.yaml and opens the streams present; throws ConfigError /
  // InputError (missing folder or metadata, unsupported format_version,
  // invalid limits). Every item read is checked against the limits: a value
  // or a time step beyond them throws InputError naming the file and the
  // line or record (e.g. "imu.csv:301: accelerometer x 1e+300 m/s^2 is
  // beyond +-392.3 m/s^2").
  explicit DatasetReader(const std::filesystem::path& folder, const DatasetLimits& limits = {});
  // A recording read directly (KITTI sequence, CARMEN log, ROS 1 or ROS 2
  // bag; `format` and `conversion` as for io::Convert, its output unused):
  // converted on a thread as it is read (LiveConversion), never written to
  // disk. The same limits apply; an error names conversion.input, the stream
  // and the item. Events are merged in time order as from a folder, except
  // that an item the conversion releases after a later one was already
  // delivered (a stream more than the queues' span behind the others) is
  // dropped and counted (late_events()). Throws what the conversion throws
  // before the dataset's metadata is known.
  DatasetReader(const std::string& format, const ConversionOptions& conversion, const DatasetLimits& limits = {});
  ~DatasetReader();
  DatasetReader(const DatasetReader&) = delete;
  DatasetReader& operator=(const DatasetReader&) = delete;

  const DatasetMetadata& metadata() const;
  // A folder: whether it has groundtruth.tum. A recording read directly:
  // whether any ground truth has been read so far (KITTI poses come first).
  bool has_groundtruth() const;
  // True when the stream still holds a sample (reads its first one ahead,
  // so a malformed first record throws InputError here). Before any Next*
  // call: whether the dataset has IMU / wheel-odometry data at all.
  bool has_imu();
  bool has_odometry();
  bool has_encoder();
  bool has_scans();

  std::optional<ImuSample> NextImu();
  std::optional<EncoderSample> NextEncoder();
  std::optional<OdometrySample> NextOdometry();
  std::optional<ScanRecord> NextScan();
  std::optional<StampedPose> NextGroundTruth();

  // All sensor streams merged in time order (scans by their end time; ties:
  // IMU, encoder, odometry, then scans): a k-way merge holding one look-ahead
  // per stream. Ground truth is not included. Mixing with the Next* calls is
  // allowed but rarely useful: a per-stream call first returns the item
  // NextEvent() holds for that stream.
  std::optional<DatasetEvent> NextEvent();

  // A recording read directly: its conversion's report once the conversion
  // has read it to the end (std::nullopt before, and for a folder).
  std::optional<ConversionReport> conversion_report() const;
  // A recording read directly: items dropped by NextEvent() for arriving
  // after a later item of another stream (0 for a folder).
  std::size_t late_events() const;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap::io
