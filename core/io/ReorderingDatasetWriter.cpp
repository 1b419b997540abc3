#include "io/ReorderingDatasetWriter.hpp"

#include <algorithm>
#include <sstream>

namespace unimap::io {
namespace {

std::string LateReason(const char* stream) {
  return std::string(stream) + ": time goes backwards by more than the reorder window (item dropped)";
}

}  // namespace

ReorderingDatasetWriter::ReorderingDatasetWriter(std::unique_ptr<DatasetSink> sink, double window_s,
                                                 ConversionReport* report)
    : writer_(std::move(sink)),
      report_(report),
      imu_(window_s),
      encoder_(window_s),
      odometry_(window_s),
      scans_(window_s),
      groundtruth_(window_s) {}

void ReorderingDatasetWriter::Extend(Span* span, double time_s) {
  span->first_s = span->any ? std::min(span->first_s, time_s) : time_s;
  span->last_s = span->any ? std::max(span->last_s, time_s) : time_s;
  span->any = true;
}

void ReorderingDatasetWriter::WriteImu(const ImuSample& sample) {
  if (!imu_.Push(sample.time_s, sample)) ++report_->skipped[LateReason("imu")];
  Drain(false);
}

void ReorderingDatasetWriter::WriteEncoder(const EncoderSample& sample) {
  if (!encoder_.Push(sample.time_s, sample)) ++report_->skipped[LateReason("encoder")];
  Drain(false);
}

void ReorderingDatasetWriter::WriteOdometry(const OdometrySample& sample) {
  if (!odometry_.Push(sample.time_s, sample)) ++report_->skipped[LateReason("odometry")];
  Drain(false);
}

void ReorderingDatasetWriter::WriteScan(ScanRecord scan) {
  const double end_time_s = ScanEndTime(scan);
  if (!scans_.Push(end_time_s, std::move(scan))) ++report_->skipped[LateReason("scans")];
  Drain(false);
}

void ReorderingDatasetWriter::WriteGroundTruth(const StampedPose& pose) {
  if (!groundtruth_.Push(pose.time_s, pose)) ++report_->skipped[LateReason("groundtruth")];
  Drain(false);
}

void ReorderingDatasetWriter::Drain(bool flush) {
  while (auto sample = imu_.Pop(flush)) {
    writer_->WriteImu(*sample);
    Extend(&imu_span_, sample->time_s);
    ++report_->imu;
  }
  while (auto sample = encoder_.Pop(flush)) {
    writer_->WriteEncoder(*sample);
    Extend(&encoder_span_, sample->time_s);
    ++report_->encoder;
  }
  while (auto sample = odometry_.Pop(flush)) {
    writer_->WriteOdometry(*sample);
    Extend(&odometry_span_, sample->time_s);
    ++report_->odometry;
  }
  while (auto scan = scans_.Pop(flush)) {
    writer_->WriteScan(*scan);
    Extend(&scan_span_, ScanEndTime(*scan));
    ++report_->scans;
  }
  while (auto pose = groundtruth_.Pop(flush)) {
    writer_->WriteGroundTruth(*pose);
    Extend(&groundtruth_span_, pose->time_s);
    ++report_->groundtruth;
  }
}

void ReorderingDatasetWriter::Finish() {
  Drain(true);
  writer_->Finish();
  // Streams on different clocks (e.g. a simulator's clock and wall time in
  // one bag) cannot be fused; say so rather than let the mapper find out.
  const Span* spans[] = {&imu_span_, &encoder_span_, &odometry_span_, &scan_span_, &groundtruth_span_};
  for (const Span* a : spans) {
    for (const Span* b : spans) {
      if (a >= b || !a->any || !b->any) continue;
      const double gap_s = std::max(a->first_s - b->last_s, b->first_s - a->last_s);
      if (gap_s > 60.0) {
        std::ostringstream note;
        note.precision(15);
        note << "streams " << a->name << " [" << a->first_s << ", " << a->last_s << "] s and " << b->name << " ["
             << b->first_s << ", " << b->last_s << "] s do not overlap (different clocks?)";
        report_->notes.push_back(note.str());
      }
    }
  }
}

}  // namespace unimap::io
