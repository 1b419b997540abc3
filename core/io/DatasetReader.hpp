#pragma once
#include <filesystem>
#include <memory>
#include <optional>
#include <variant>

#include "io/DatasetMetadata.hpp"
#include "io/ScanRecord.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::io {

// One time-stamped item of a dataset.
using DatasetEvent = std::variant<ImuSample, EncoderSample, OdometrySample, ScanRecord>;

// Streams a dataset folder without holding it in memory. Per-stream readers
// return std::nullopt at the end of a stream; a malformed or truncated record
// throws InputError naming the file and the record (line or index).
class DatasetReader {
 public:
  // Reads metadata.yaml and opens the streams present; throws ConfigError /
  // InputError (missing folder or metadata, unsupported format_version).
  explicit DatasetReader(const std::filesystem::path& folder);
  ~DatasetReader();
  DatasetReader(const DatasetReader&) = delete;
  DatasetReader& operator=(const DatasetReader&) = delete;

  const DatasetMetadata& metadata() const;
  bool has_groundtruth() const;

  std::optional<ImuSample> NextImu();
  std::optional<EncoderSample> NextEncoder();
  std::optional<OdometrySample> NextOdometry();
  std::optional<ScanRecord> NextScan();
  std::optional<StampedPose> NextGroundTruth();

  // All sensor streams merged in time order (scans by their end time; ties:
  // IMU, encoder, odometry, then scans). Do not mix with the Next* calls.
  std::optional<DatasetEvent> NextEvent();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap::io
