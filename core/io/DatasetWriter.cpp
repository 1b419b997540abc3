#include "io/DatasetWriter.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

#include "io/DatasetLayout.hpp"
#include "io/NumberText.hpp"
#include "io/PartialFile.hpp"
#include "io/ScanCodec.hpp"
#include "io/TumLine.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

std::string Text(double value) {
  std::string out;
  AppendNumber(&out, value);
  return out;
}

// One output stream: its file, opened on the first item, and the time order.
struct Stream {
  const char* name;                 // file name in the folder
  const char* header;               // text header line; nullptr for scans.bin
  std::optional<PartialFile> file;  // "<name>.partial" once an item was written
  double last_time_s = 0.0;         // time of the previous item
  bool has_last = false;            // an item was written
};

}  // namespace

class DatasetWriter::Impl {
 public:
  Impl(std::filesystem::path folder, DatasetMetadata metadata)
      : folder_(std::move(folder)), metadata_(std::move(metadata)) {}

  // Throws unless `time_s` is finite and not before the stream's previous item.
  void CheckTime(Stream& stream, double time_s) {
    if (finished_) throw InputError(folder_.string() + ": write after DatasetWriter::Finish()");
    if (!std::isfinite(time_s)) {
      throw InputError(folder_.string() + ": " + stream.name + ": time " + Text(time_s) + " is not finite");
    }
    if (stream.has_last && time_s < stream.last_time_s) {
      throw InputError(folder_.string() + ": " + stream.name + ": time goes backwards: " + Text(time_s) + " s after " +
                       Text(stream.last_time_s) + " s (every stream must be non-decreasing in time)");
    }
  }

  // Writes `bytes` as the stream's next item at `time_s` (span: [first, last]).
  void Append(Stream& stream, double time_s, double first_s, double last_s, const std::string& bytes) {
    if (!stream.file) {
      stream.file.emplace(folder_ / stream.name);
      if (stream.header != nullptr) {
        stream.file->Write(stream.header);
      } else {
        std::string header;
        AppendScanFileHeader(&header);
        stream.file->Write(header);
      }
    }
    stream.file->Write(bytes);
    stream.last_time_s = time_s;
    stream.has_last = true;
    min_time_s_ = has_time_ ? std::min(min_time_s_, first_s) : first_s;
    max_time_s_ = has_time_ ? std::max(max_time_s_, last_s) : last_s;
    has_time_ = true;
  }

  // A pose stream row: time, translation, quaternion.
  void WritePose(Stream& stream, double time_s, const Eigen::Isometry3d& pose) {
    CheckTime(stream, time_s);
    const std::string problem = TumPoseProblem(time_s, pose);
    if (!problem.empty()) throw InputError(folder_.string() + ": " + stream.name + ": " + problem);
    line_.clear();
    AppendTumRow(&line_, time_s, pose);
    Append(stream, time_s, time_s, time_s, line_);
  }

  void Finish() {
    if (finished_) throw InputError(folder_.string() + ": DatasetWriter::Finish() called twice");
    finished_ = true;
    for (Stream* stream : {&imu_, &encoder_, &odometry_, &scans_, &groundtruth_}) {
      if (stream->file) {
        stream->file->Commit();
        continue;
      }
      std::error_code ec;  // an older dataset's file of a stream not written now
      std::filesystem::remove(folder_ / stream->name, ec);
      if (ec) {
        throw InputError((folder_ / stream->name).string() + ": cannot remove: " + ec.message());
      }
    }
    metadata_.format_version = 1;
    metadata_.duration_s = has_time_ ? max_time_s_ - min_time_s_ : 0.0;
    SaveDatasetMetadata(metadata_, folder_ / layout::kMetadata);
  }

  std::filesystem::path folder_;  // the dataset folder
  DatasetMetadata metadata_;      // written by Finish()
  Stream imu_{layout::kImu, layout::kImuHeader, {}};
  Stream encoder_{layout::kEncoder, layout::kEncoderHeader, {}};
  Stream odometry_{layout::kOdometry, layout::kPoseHeader, {}};
  Stream scans_{layout::kScans, nullptr, {}};
  Stream groundtruth_{layout::kGroundTruth, layout::kPoseHeader, {}};
  std::string line_;         // reused text / record bytes
  double min_time_s_ = 0.0;  // earliest time written (any stream)
  double max_time_s_ = 0.0;  // latest time written (any stream)
  bool has_time_ = false;    // anything was written
  bool finished_ = false;    // Finish() was called
};

DatasetWriter::DatasetWriter(const std::filesystem::path& folder, DatasetMetadata metadata)
    : impl_(std::make_unique<Impl>(folder, std::move(metadata))) {
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec || !std::filesystem::is_directory(folder)) {
    throw InputError(folder.string() + ": cannot create the dataset folder" +
                     (ec ? ": " + ec.message() : std::string()));
  }
  // Rewriting a folder: drop the old metadata first, so an interrupted rewrite
  // reads as incomplete rather than as the old dataset with new streams.
  std::filesystem::remove(folder / layout::kMetadata, ec);
  if (ec) throw InputError((folder / layout::kMetadata).string() + ": cannot remove: " + ec.message());
}

DatasetWriter::~DatasetWriter() = default;

void DatasetWriter::WriteImu(const ImuSample& sample) {
  impl_->CheckTime(impl_->imu_, sample.time_s);
  std::string& line = impl_->line_;
  line.clear();
  AppendNumber(&line, sample.time_s);
  for (const double value : {sample.accel_m_s2.x(), sample.accel_m_s2.y(), sample.accel_m_s2.z(), sample.gyro_rad_s.x(),
                             sample.gyro_rad_s.y(), sample.gyro_rad_s.z()}) {
    line.push_back(' ');
    AppendNumber(&line, value);
  }
  line.push_back('\n');
  impl_->Append(impl_->imu_, sample.time_s, sample.time_s, sample.time_s, line);
}

void DatasetWriter::WriteEncoder(const EncoderSample& sample) {
  impl_->CheckTime(impl_->encoder_, sample.time_s);
  std::string& line = impl_->line_;
  line.clear();
  AppendNumber(&line, sample.time_s);
  line.push_back(' ');
  AppendNumber(&line, sample.angle_rad);
  line.push_back('\n');
  impl_->Append(impl_->encoder_, sample.time_s, sample.time_s, sample.time_s, line);
}

void DatasetWriter::WriteOdometry(const OdometrySample& sample) {
  impl_->WritePose(impl_->odometry_, sample.time_s, sample.T_odom_body);
}

void DatasetWriter::WriteGroundTruth(const StampedPose& pose) {
  impl_->WritePose(impl_->groundtruth_, pose.time_s, pose.T_map_body);
}

void DatasetWriter::WriteScan(const ScanRecord& scan) {
  const std::string problem = ScanRecordProblem(scan);
  if (!problem.empty()) {
    throw InputError(impl_->folder_.string() + ": " + layout::kScans + ": " + problem);
  }
  const double end_time_s = ScanEndTime(scan);
  impl_->CheckTime(impl_->scans_, end_time_s);
  std::string& record = impl_->line_;
  record.clear();
  AppendScanRecord(&record, scan);
  impl_->Append(impl_->scans_, end_time_s, std::min(ScanStartTime(scan), end_time_s), end_time_s, record);
}

void DatasetWriter::Finish() { impl_->Finish(); }

}  // namespace unimap::io
