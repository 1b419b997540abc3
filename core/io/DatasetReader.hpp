#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <variant>

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
  ~DatasetReader();
  DatasetReader(const DatasetReader&) = delete;
  DatasetReader& operator=(const DatasetReader&) = delete;

  const DatasetMetadata& metadata() const;
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

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap::io
