#pragma once
#include <filesystem>
#include <memory>

#include "io/DatasetMetadata.hpp"
#include "io/DatasetSink.hpp"
#include "io/ScanRecord.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::io {

// Streams a dataset folder to disk (docs/dataset-format.md): every stream is
// written to "<name>.partial" and renamed by Finish(), so an interrupted
// writer never leaves a file that looks complete. Each stream must be written
// in non-decreasing time order (InputError otherwise, naming the stream; the
// rejected item is not written and the writer stays usable). A stream's file
// is created by its first item: a stream never written has no file.
// Destroying the writer without Finish() (an error, a full disk) removes the
// ".partial" files it was writing and leaves no metadata.yaml, which readers
// report as an incomplete dataset.
class DatasetWriter final : public DatasetSink {
 public:
  // Creates the folder if needed; throws InputError if it cannot. An existing
  // metadata.yaml in it is removed at once (the folder is being rewritten).
  DatasetWriter(const std::filesystem::path& folder, DatasetMetadata metadata);
  ~DatasetWriter() override;
  DatasetWriter(const DatasetWriter&) = delete;
  DatasetWriter& operator=(const DatasetWriter&) = delete;

  // Each throws InputError for a non-finite time, time before the stream's
  // previous item, a write after Finish() or a failed write.
  void WriteImu(const ImuSample& sample) override;
  void WriteEncoder(const EncoderSample& sample) override;
  // Also throws when T_odom_body is not finite or its linear part is not a rotation.
  void WriteOdometry(const OdometrySample& sample) override;
  // Ordered by ScanEndTime(). Also throws for a scan the format cannot hold
  // (non-finite times, RawScan ending before it starts, intensities neither
  // empty nor one per beam).
  void WriteScan(const ScanRecord& scan) override;
  // Also throws when T_map_body is not finite or its linear part is not a rotation.
  void WriteGroundTruth(const StampedPose& pose) override;
  // Flushes, renames every stream into place, removes stream files an older
  // dataset left in the folder, then writes metadata.yaml (format_version 1,
  // duration_s = latest minus earliest time of any stream). Further writes
  // and a second Finish() are InputErrors.
  void Finish() override;

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap::io
