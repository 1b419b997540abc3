#include "io/DatasetReader.hpp"

#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <type_traits>
#include <utility>
#include <variant>

#include "io/DatasetLayout.hpp"
#include "io/LiveConversion.hpp"
#include "io/LiveStreamCheck.hpp"
#include "io/NumberLineStream.hpp"
#include "io/RawInput.hpp"
#include "io/ScanFileReader.hpp"
#include "io/TumLine.hpp"
#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// Opens folder/name as T(path, args...) when the file exists; a missing
// stream file is an empty stream.
template <typename T, typename... Args>
std::unique_ptr<T> OpenIfPresent(const std::filesystem::path& folder, const char* name, Args... args) {
  std::error_code ec;
  if (!std::filesystem::exists(folder / name, ec)) return nullptr;
  return std::make_unique<T>(folder / name, args...);
}

}  // namespace

class DatasetReader::Impl {
 public:
  Impl(const std::filesystem::path& folder, const DatasetLimits& limits)
      : limits_(CheckedLimits(limits)),
        metadata_(LoadChecked(folder)),
        imu_(OpenIfPresent<NumberLineStream>(folder, layout::kImu, layout::kImuColumns)),
        encoder_(OpenIfPresent<NumberLineStream>(folder, layout::kEncoder, layout::kEncoderColumns)),
        odometry_(OpenIfPresent<NumberLineStream>(folder, layout::kOdometry, kTumColumns)),
        scans_(OpenIfPresent<ScanFileReader>(folder, layout::kScans)),
        groundtruth_(OpenIfPresent<NumberLineStream>(folder, layout::kGroundTruth, kTumColumns)) {
    const double max_s = limits_.max_abs_time_s;
    if (imu_) imu_->SetTimeLimits(max_s, limits_.max_imu_step_s);
    if (encoder_) encoder_->SetTimeLimits(max_s, limits_.max_encoder_step_s);
    if (odometry_) odometry_->SetTimeLimits(max_s, limits_.max_odometry_step_s);
    if (groundtruth_) groundtruth_->SetTimeLimits(max_s, HUGE_VAL);  // not integrated: gaps are fine
    if (scans_) scans_->SetLimits(limits_);
  }

  Impl(const std::string& format, const ConversionOptions& conversion, const DatasetLimits& limits)
      : limits_(CheckedLimits(limits)),
        input_(conversion.input),
        live_(std::make_unique<LiveConversion>(format, conversion)),
        metadata_(live_->metadata()) {}

  static DatasetLimits CheckedLimits(const DatasetLimits& limits) {
    std::string why;
    if (!limits.IsValid(&why)) throw ConfigError("", 0, "", "dataset limits: " + why);
    return limits;
  }

  // Calls rows.Fail(problem) unless problem is empty.
  static void Check(const NumberLineStream& rows, const std::string& problem) {
    if (!problem.empty()) rows.Fail(problem);
  }

  static DatasetMetadata LoadChecked(const std::filesystem::path& folder) {
    // A raw recording is looked for only when the folder is not a dataset,
    // so opening a dataset costs no second read of its metadata.
    const auto not_a_dataset = [&folder](const std::string& reason) {
      if (const std::optional<RawInput> raw = DetectRawInput(folder)) throw InputError(ConvertAdvice(folder, *raw));
      throw InputError(folder.string() + reason);
    };
    std::error_code ec;
    if (!std::filesystem::is_directory(folder, ec)) {
      not_a_dataset(std::filesystem::exists(folder, ec) ? ": a file, not a dataset folder"
                                                        : ": no such dataset folder");
    }
    if (!std::filesystem::exists(folder / layout::kMetadata, ec)) {
      not_a_dataset(
          ": no metadata.yaml: not a dataset, or an incomplete one (a writer "
          "that did not finish leaves only .partial files)");
    }
    try {
      return LoadDatasetMetadata(folder / layout::kMetadata);
    } catch (const ConfigError&) {
      // A ROS 2 bag folder has a metadata.yaml of its own.
      if (const std::optional<RawInput> raw = DetectRawInput(folder)) throw InputError(ConvertAdvice(folder, *raw));
      throw;
    }
  }

  std::optional<ImuSample> ReadImu() {
    if (live_) {
      std::optional<ImuSample> sample = live_->NextImu();
      if (sample) live_imu_.Check(input_, limits_, sample->time_s, limits_.ImuProblem(*sample));
      return sample;
    }
    double v[layout::kImuColumns];
    if (!imu_ || !imu_->Next(v)) return std::nullopt;
    ImuSample sample;
    sample.time_s = v[0];
    sample.accel_m_s2 = Eigen::Vector3d(v[1], v[2], v[3]);
    sample.gyro_rad_s = Eigen::Vector3d(v[4], v[5], v[6]);
    Check(*imu_, limits_.ImuProblem(sample));
    return sample;
  }

  std::optional<EncoderSample> ReadEncoder() {
    if (live_) {
      std::optional<EncoderSample> sample = live_->NextEncoder();
      if (sample) live_encoder_.Check(input_, limits_, sample->time_s, limits_.EncoderProblem(*sample));
      return sample;
    }
    double v[layout::kEncoderColumns];
    if (!encoder_ || !encoder_->Next(v)) return std::nullopt;
    const EncoderSample sample{v[0], v[1]};
    Check(*encoder_, limits_.EncoderProblem(sample));
    return sample;
  }

  std::optional<OdometrySample> ReadOdometry() {
    if (live_) {
      std::optional<OdometrySample> sample = live_->NextOdometry();
      if (sample) {
        live_odometry_.Check(input_, limits_, sample->time_s,
                             limits_.PositionProblem(sample->T_odom_body.translation()));
      }
      return sample;
    }
    double v[kTumColumns];
    if (!odometry_ || !odometry_->Next(v)) return std::nullopt;
    OdometrySample sample;
    sample.time_s = v[0];
    sample.T_odom_body = TumRowPose(v, *odometry_);
    Check(*odometry_, limits_.PositionProblem(sample.T_odom_body.translation()));
    return sample;
  }

  std::optional<ScanRecord> ReadScan() {
    if (live_) {
      std::optional<ScanRecord> scan = live_->NextScan();
      if (scan) live_scans_.Check(input_, limits_, ScanEndTime(*scan), limits_.ScanProblem(*scan));
      return scan;
    }
    return scans_ ? scans_->Next() : std::nullopt;
  }

  std::optional<StampedPose> ReadGroundTruth() {
    if (live_) return live_->NextGroundTruth();
    double v[kTumColumns];
    if (!groundtruth_ || !groundtruth_->Next(v)) return std::nullopt;
    StampedPose pose;
    pose.time_s = v[0];
    pose.T_map_body = TumRowPose(v, *groundtruth_);
    Check(*groundtruth_, limits_.PositionProblem(pose.T_map_body.translation()));
    return pose;
  }

  // The held look-ahead if any (left by NextEvent), else the next item read.
  template <typename T>
  std::optional<T> Take(std::optional<T>* ahead, std::optional<T> (Impl::*read)()) {
    if (*ahead) return std::exchange(*ahead, std::nullopt);
    return (this->*read)();
  }

  // The merge; a recording read directly drops (and counts) an event
  // earlier than one already delivered.
  std::optional<DatasetEvent> NextEvent() {
    while (true) {
      std::optional<DatasetEvent> event = NextMerged();
      if (!event || !live_) return event;
      const double time_s = EventTime(*event);
      if (delivered_any_ && time_s < last_delivered_s_) {
        ++late_events_;
        continue;
      }
      delivered_any_ = true;
      last_delivered_s_ = time_s;
      return event;
    }
  }

  // k-way merge: one look-ahead per stream, the earliest is returned; ties
  // go to the stream listed first (IMU, encoder, odometry, scans).
  std::optional<DatasetEvent> NextMerged() {
    if (!imu_ahead_) imu_ahead_ = ReadImu();
    if (!encoder_ahead_) encoder_ahead_ = ReadEncoder();
    if (!odometry_ahead_) odometry_ahead_ = ReadOdometry();
    if (!scan_ahead_) scan_ahead_ = ReadScan();
    const bool present[4] = {imu_ahead_.has_value(), encoder_ahead_.has_value(), odometry_ahead_.has_value(),
                             scan_ahead_.has_value()};
    const double time_s[4] = {imu_ahead_ ? imu_ahead_->time_s : 0.0, encoder_ahead_ ? encoder_ahead_->time_s : 0.0,
                              odometry_ahead_ ? odometry_ahead_->time_s : 0.0,
                              scan_ahead_ ? ScanEndTime(*scan_ahead_) : 0.0};
    int best = -1;
    for (int i = 0; i < 4; ++i) {
      if (present[i] && (best < 0 || time_s[i] < time_s[best])) best = i;
    }
    switch (best) {
      case 0:
        return DatasetEvent(std::in_place_type<ImuSample>, *std::exchange(imu_ahead_, {}));
      case 1:
        return DatasetEvent(std::in_place_type<EncoderSample>, *std::exchange(encoder_ahead_, {}));
      case 2:
        return DatasetEvent(std::in_place_type<OdometrySample>, *std::exchange(odometry_ahead_, {}));
      case 3:
        return DatasetEvent(std::in_place_type<ScanRecord>, *std::exchange(scan_ahead_, {}));
      default:
        return std::nullopt;
    }
  }

  DatasetLimits limits_;                           // plausibility limits of every item read
  std::filesystem::path input_;                    // a recording read directly
  std::unique_ptr<LiveConversion> live_;           // its conversion, else null
  DatasetMetadata metadata_;                       // metadata.yaml
  std::unique_ptr<NumberLineStream> imu_;          // imu.csv, if present
  std::unique_ptr<NumberLineStream> encoder_;      // encoder.csv, if present
  std::unique_ptr<NumberLineStream> odometry_;     // odometry.csv, if present
  std::unique_ptr<ScanFileReader> scans_;          // scans.bin, if present
  std::unique_ptr<NumberLineStream> groundtruth_;  // groundtruth.tum, if present
  // At most one item held per stream: the look-aheads of NextEvent().
  std::optional<ImuSample> imu_ahead_;
  std::optional<EncoderSample> encoder_ahead_;
  std::optional<OdometrySample> odometry_ahead_;
  std::optional<ScanRecord> scan_ahead_;
  // A recording read directly: the checks per stream, and the merge's order.
  LiveStreamCheck live_imu_{"imu", limits_.max_imu_step_s};
  LiveStreamCheck live_encoder_{"encoder", limits_.max_encoder_step_s};
  LiveStreamCheck live_odometry_{"odometry", limits_.max_odometry_step_s};
  LiveStreamCheck live_scans_{"scans", limits_.max_scan_step_s};
  bool delivered_any_ = false;
  double last_delivered_s_ = 0.0;
  std::size_t late_events_ = 0;
};

double EventTime(const DatasetEvent& event) {
  return std::visit(
      [](const auto& item) {
        if constexpr (std::is_same_v<std::decay_t<decltype(item)>, ScanRecord>) {
          return ScanEndTime(item);
        } else {
          return item.time_s;
        }
      },
      event);
}

DatasetReader::DatasetReader(const std::filesystem::path& folder, const DatasetLimits& limits)
    : impl_(std::make_unique<Impl>(folder, limits)) {}

DatasetReader::DatasetReader(const std::string& format, const ConversionOptions& conversion,
                             const DatasetLimits& limits)
    : impl_(std::make_unique<Impl>(format, conversion, limits)) {}

DatasetReader::~DatasetReader() = default;

const DatasetMetadata& DatasetReader::metadata() const { return impl_->metadata_; }

bool DatasetReader::has_groundtruth() const {
  return impl_->live_ ? impl_->live_->has_groundtruth() : impl_->groundtruth_ != nullptr;
}

bool DatasetReader::has_imu() {
  if (!impl_->imu_ahead_) impl_->imu_ahead_ = impl_->ReadImu();
  return impl_->imu_ahead_.has_value();
}

bool DatasetReader::has_odometry() {
  if (!impl_->odometry_ahead_) impl_->odometry_ahead_ = impl_->ReadOdometry();
  return impl_->odometry_ahead_.has_value();
}

bool DatasetReader::has_encoder() {
  if (!impl_->encoder_ahead_) impl_->encoder_ahead_ = impl_->ReadEncoder();
  return impl_->encoder_ahead_.has_value();
}

bool DatasetReader::has_scans() {
  if (!impl_->scan_ahead_) impl_->scan_ahead_ = impl_->ReadScan();
  return impl_->scan_ahead_.has_value();
}

std::optional<ImuSample> DatasetReader::NextImu() { return impl_->Take(&impl_->imu_ahead_, &Impl::ReadImu); }

std::optional<EncoderSample> DatasetReader::NextEncoder() {
  return impl_->Take(&impl_->encoder_ahead_, &Impl::ReadEncoder);
}

std::optional<OdometrySample> DatasetReader::NextOdometry() {
  return impl_->Take(&impl_->odometry_ahead_, &Impl::ReadOdometry);
}

std::optional<ScanRecord> DatasetReader::NextScan() { return impl_->Take(&impl_->scan_ahead_, &Impl::ReadScan); }

std::optional<StampedPose> DatasetReader::NextGroundTruth() { return impl_->ReadGroundTruth(); }

std::optional<DatasetEvent> DatasetReader::NextEvent() { return impl_->NextEvent(); }

std::optional<ConversionReport> DatasetReader::conversion_report() const {
  return impl_->live_ ? impl_->live_->report() : std::nullopt;
}

std::size_t DatasetReader::late_events() const { return impl_->late_events_; }

}  // namespace unimap::io
