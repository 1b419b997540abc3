#pragma once
#include "io/ScanRecord.hpp"
#include "unimap/EncoderSample.hpp"
#include "unimap/ImuSample.hpp"
#include "unimap/OdometrySample.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::io {

// Where a conversion (io/DatasetConversion.hpp) puts what it reads: a
// dataset folder (DatasetWriter) or a run reading the recording directly
// (LiveConversion). Callers write each stream in non-decreasing time order
// (scans by ScanEndTime) and call Finish() once after the last item
// (DatasetWriter throws InputError on a violation; a live run's reader
// drops and counts an item out of order, DatasetReader::late_events).
class DatasetSink {
 public:
  virtual ~DatasetSink() = default;
  virtual void WriteImu(const ImuSample& sample) = 0;
  virtual void WriteEncoder(const EncoderSample& sample) = 0;
  virtual void WriteOdometry(const OdometrySample& sample) = 0;
  virtual void WriteScan(const ScanRecord& scan) = 0;
  virtual void WriteGroundTruth(const StampedPose& pose) = 0;
  virtual void Finish() = 0;
};

}  // namespace unimap::io
