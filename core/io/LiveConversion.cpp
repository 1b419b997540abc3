#include "io/LiveConversion.hpp"

#include <type_traits>
#include <utility>
#include <variant>

#include "unimap/Errors.hpp"

namespace unimap::io {
namespace {

// Thrown into the conversion's thread when the reader no longer wants items.
struct Cancelled {};

// Points (beams) of a scan; 0 for other items.
template <typename T>
std::size_t Points(const T& item) {
  if constexpr (std::is_same_v<T, ScanRecord>) {
    return std::visit(
        [](const auto& scan) -> std::size_t {
          if constexpr (std::is_same_v<std::decay_t<decltype(scan)>, LineScan>) {
            return scan.ranges_m.size();
          } else {
            return scan.points.size();
          }
        },
        item);
  } else {
    (void)item;
    return 0;
  }
}

}  // namespace

// The conversion's DatasetSink: appends to the queues, waiting while they are full.
class LiveConversion::Sink final : public DatasetSink {
 public:
  explicit Sink(LiveConversion* owner) : owner_(owner) {}
  void WriteImu(const ImuSample& sample) override { Push(&owner_->imu_, sample); }
  void WriteEncoder(const EncoderSample& sample) override { Push(&owner_->encoder_, sample); }
  void WriteOdometry(const OdometrySample& sample) override { Push(&owner_->odometry_, sample); }
  void WriteScan(const ScanRecord& scan) override { Push(&owner_->scans_, scan); }
  void WriteGroundTruth(const StampedPose& pose) override {
    const std::lock_guard<std::mutex> lock(owner_->mutex_);
    if (owner_->cancelled_) throw Cancelled{};
    owner_->groundtruth_.push_back(std::make_unique<StampedPose>(pose));  // small: never waits
    owner_->any_groundtruth_ = true;
  }
  void Finish() override {}

 private:
  template <typename T>
  void Push(Queue<T>* queue, const T& item) {
    std::unique_lock<std::mutex> lock(owner_->mutex_);
    owner_->changed_.wait(lock, [this] { return owner_->cancelled_ || !owner_->Full(); });
    if (owner_->cancelled_) throw Cancelled{};
    queue->push_back(std::make_unique<T>(item));
    ++owner_->items_;
    owner_->scan_points_ += Points(item);
    owner_->changed_.notify_all();
  }

  LiveConversion* owner_;
};

LiveConversion::LiveConversion(std::string format, ConversionOptions options, QueueLimits limits) : limits_(limits) {
  options.stop = &stop_;
  options.open_sink = [this](const DatasetMetadata& metadata) -> std::unique_ptr<DatasetSink> {
    const std::lock_guard<std::mutex> lock(mutex_);
    metadata_ = metadata;
    has_metadata_ = true;
    changed_.notify_all();
    return std::make_unique<Sink>(this);
  };
  thread_ = std::thread([this, format = std::move(format), options = std::move(options)]() mutable {
    Produce(format, std::move(options));
  });
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [this] { return has_metadata_ || done_; });
  if (!has_metadata_) {
    const std::exception_ptr error = error_;
    lock.unlock();
    thread_.join();
    if (error) std::rethrow_exception(error);
    throw InputError("the conversion ended before it described the dataset");
  }
}

LiveConversion::~LiveConversion() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    cancelled_ = true;
    stop_ = true;
    changed_.notify_all();
  }
  if (thread_.joinable()) thread_.join();
}

void LiveConversion::Produce(const std::string& format, ConversionOptions options) {
  std::optional<ConversionReport> report;
  std::exception_ptr error;
  try {
    report = Convert(format, options);
  } catch (const Cancelled&) {
  } catch (...) {
    error = std::current_exception();
  }
  const std::lock_guard<std::mutex> lock(mutex_);
  // A conversion stopped by the destructor reports nothing: it did not end by itself.
  if (!stop_) report_ = std::move(report);
  error_ = error;
  done_ = true;
  changed_.notify_all();
}

bool LiveConversion::Full() const {
  return items_ >= limits_.max_items || scans_.size() >= limits_.max_scans || scan_points_ >= limits_.max_scan_points;
}

template <typename T>
std::optional<T> LiveConversion::Take(Queue<T>* queue) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return !queue->empty() || done_ || Full(); });
  if (queue->empty()) {
    if (done_ && error_ && items_ == 0) std::rethrow_exception(std::exchange(error_, nullptr));
    return std::nullopt;
  }
  const std::unique_ptr<T> item = std::move(queue->front());
  queue->pop_front();
  scan_points_ -= Points(*item);
  --items_;
  changed_.notify_all();
  return std::optional<T>(std::move(*item));
}

std::optional<ImuSample> LiveConversion::NextImu() { return Take(&imu_); }
std::optional<EncoderSample> LiveConversion::NextEncoder() { return Take(&encoder_); }
std::optional<OdometrySample> LiveConversion::NextOdometry() { return Take(&odometry_); }
std::optional<ScanRecord> LiveConversion::NextScan() { return Take(&scans_); }

std::optional<StampedPose> LiveConversion::NextGroundTruth() {
  const std::lock_guard<std::mutex> lock(mutex_);
  if (groundtruth_.empty()) return std::nullopt;
  const StampedPose pose = *groundtruth_.front();
  groundtruth_.pop_front();
  return pose;
}

bool LiveConversion::has_groundtruth() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return any_groundtruth_;
}

std::optional<ConversionReport> LiveConversion::report() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return report_;
}

}  // namespace unimap::io
