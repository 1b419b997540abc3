#pragma once
#include <filesystem>
#include <fstream>
#include <memory>

#include "io/DatasetMetadata.hpp"
#include "io/ScanRecord.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::io {

// Streams a dataset folder to disk (docs/dataset-format.md): every stream is
// written to "<name>.partial" and renamed by Finish(), so an interrupted
// writer never leaves a file that looks complete. Each stream must be written
// in non-decreasing time order (InputError otherwise).
class DatasetWriter {
 public:
  // Creates the folder if needed; throws InputError if it cannot.
  DatasetWriter(const std::filesystem::path& folder, DatasetMetadata metadata);
  ~DatasetWriter();
  DatasetWriter(const DatasetWriter&) = delete;
  DatasetWriter& operator=(const DatasetWriter&) = delete;

  void WriteImu(const ImuSample& sample);
  void WriteEncoder(const EncoderSample& sample);
  void WriteOdometry(const OdometrySample& sample);
  void WriteScan(const ScanRecord& scan);
  void WriteGroundTruth(const StampedPose& pose);
  // Flushes, renames every stream into place and writes metadata.yaml (with
  // duration_s updated from the data). Further writes are errors.
  void Finish();

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace unimap::io
