#include "unimap/Dataset.hpp"

#include <filesystem>

#include "io/DatasetReader.hpp"
#include "io/TumTrajectory.hpp"

namespace unimap {

class Dataset::Impl {
 public:
  explicit Impl(const std::string& folder) : folder_(folder), reader_(folder_) {
    const io::DatasetMetadata& metadata = reader_.metadata();
    info_.payload = metadata.payload;
    info_.scenario = metadata.scenario;
    info_.duration_s = metadata.duration_s;
    info_.has_imu = reader_.has_imu();
    info_.has_encoder = reader_.has_encoder();
    info_.has_odometry = reader_.has_odometry();
    info_.has_groundtruth = reader_.has_groundtruth();
  }

  std::optional<DatasetEvent> Next() {
    std::optional<io::DatasetEvent> event = reader_.NextEvent();
    if (!event) return std::nullopt;
    if (auto* imu = std::get_if<ImuSample>(&*event)) return DatasetEvent(*imu);
    if (auto* encoder = std::get_if<EncoderSample>(&*event)) return DatasetEvent(*encoder);
    if (auto* odometry = std::get_if<OdometrySample>(&*event)) return DatasetEvent(*odometry);
    io::ScanRecord& scan = std::get<io::ScanRecord>(*event);
    if (auto* line = std::get_if<LineScan>(&scan)) return DatasetEvent(std::move(*line));
    return DatasetEvent(std::move(std::get<RawScan>(scan)));
  }

  std::vector<StampedPose> GroundTruth() const {
    if (!info_.has_groundtruth) return {};
    return io::ReadTumTrajectory(folder_ / "groundtruth.tum");
  }

  const DatasetInfo& info() const { return info_; }

 private:
  std::filesystem::path folder_;
  io::DatasetReader reader_;
  DatasetInfo info_;
};

Dataset::Dataset(const std::string& folder) : impl_(std::make_unique<Impl>(folder)) {}
Dataset::~Dataset() = default;
const DatasetInfo& Dataset::info() const { return impl_->info(); }
std::optional<DatasetEvent> Dataset::Next() { return impl_->Next(); }
std::vector<StampedPose> Dataset::GroundTruth() const { return impl_->GroundTruth(); }

}  // namespace unimap
