#pragma once
// Internal to unimap_io: a DatasetWriter that puts slightly out-of-order
// streams back in time order (used by the real-data conversions).
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "io/DatasetConversion.hpp"
#include "io/DatasetSink.hpp"
#include "io/TimeReorderBuffer.hpp"

namespace unimap::io {

// Writes each stream through a TimeReorderBuffer of window_s; an item that
// arrives later than the window allows is not written and is counted in the
// report as skipped ("<stream>: time goes backwards by more than the reorder
// window"). Written items are counted in the report too.
class ReorderingDatasetWriter {
 public:
  // Writes into sink (a dataset folder or a live run: OpenDatasetSink); the
  // report must outlive this object.
  ReorderingDatasetWriter(std::unique_ptr<DatasetSink> sink, double window_s, ConversionReport* report);

  void WriteImu(const ImuSample& sample);
  void WriteEncoder(const EncoderSample& sample);
  void WriteOdometry(const OdometrySample& sample);
  void WriteScan(ScanRecord scan);
  void WriteGroundTruth(const StampedPose& pose);
  // Releases every held item, then DatasetSink::Finish(). Adds a note when
  // the written streams' time spans do not overlap (sensors on different clocks).
  void Finish();

 private:
  // Time span of one written stream.
  struct Span {
    const char* name;
    double first_s = 0.0;
    double last_s = 0.0;
    bool any = false;
  };
  // Writes the released items of every buffer (all of them when flushing).
  void Drain(bool flush);
  static void Extend(Span* span, double time_s);

  std::unique_ptr<DatasetSink> writer_;
  ConversionReport* report_;
  TimeReorderBuffer<ImuSample> imu_;
  TimeReorderBuffer<EncoderSample> encoder_;
  TimeReorderBuffer<OdometrySample> odometry_;
  TimeReorderBuffer<ScanRecord> scans_;
  TimeReorderBuffer<StampedPose> groundtruth_;
  Span imu_span_{"imu"}, encoder_span_{"encoder"}, odometry_span_{"odometry"}, scan_span_{"scans"},
      groundtruth_span_{"groundtruth"};
};

}  // namespace unimap::io
