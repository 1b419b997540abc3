#include "unimap/Mapper.hpp"

#include <algorithm>
#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <utility>
#include <variant>

#include "EventMerge.hpp"
#include "io/PcdWriter.hpp"
#include "io/PlyWriter.hpp"
#include "pipeline/Mapper.hpp"
#include "pipeline/MapperSettings.hpp"
#include "unimap/Errors.hpp"
#include "unimap/Platform.hpp"

namespace unimap {
namespace {

estimation::MotionSource SourceOf(MotionModel motion) {
  switch (motion) {
    case MotionModel::kImu:
      return estimation::MotionSource::kImu;
    case MotionModel::kOdometry:
      return estimation::MotionSource::kWheelOdometry;
    case MotionModel::kConstantVelocity:
      return estimation::MotionSource::kConstantVelocity;
  }
  return estimation::MotionSource::kImu;
}

// The merge waits for the streams the settings and the payload say will deliver.
std::array<bool, api::kStreams> ExpectedStreams(const MapperSettings& settings, const PayloadPlugin& plugin) {
  std::array<bool, api::kStreams> expected{};
  expected[static_cast<std::size_t>(api::Stream::kImu)] = settings.motion == MotionModel::kImu;
  expected[static_cast<std::size_t>(api::Stream::kEncoder)] = settings.encoder_stream && plugin.UsesEncoder();
  expected[static_cast<std::size_t>(api::Stream::kOdometry)] =
      settings.odometry_stream || settings.motion == MotionModel::kOdometry;
  expected[static_cast<std::size_t>(api::Stream::kScan)] = true;
  return expected;
}

pipeline::MapperOptions OptionsFor(const MapperSettings& settings, const Platform& platform,
                                   const pipeline::SceneScale& scene) {
  // As `unimap run` builds them (tools/unimap/MappingRun.cpp), so that
  // kSynchronous gives its results.
  pipeline::MapperOptions options = pipeline::MapperOptionsFor(platform, scene);
  options.localizer.gpf.threads = settings.threads;
  if (!settings.loop_closure) options.loop_search.enabled = false;
  options.localizer.motion.source = SourceOf(settings.motion);
  if (settings.mode == MapperMode::kLive) {
    options.localizer.wait_for_map = false;
    options.wait_for_background = false;
  }
  return options;
}

// The options at the platform's own voxel, checked as the mapper checks
// them: a bad `mapper:` section fails here, not at the first 3D scan.
pipeline::MapperOptions CheckedOptions(const MapperSettings& settings, const Platform& platform) {
  const pipeline::MapperOptions options = OptionsFor(settings, platform, {});
  std::string why;
  if (!options.IsValid(&why)) throw ConfigError("", 0, "", "mapper options: " + why);
  return options;
}

MapperSettings Validated(const MapperSettings& settings) {
  std::string why;
  if (!settings.IsValid(&why)) throw ConfigError("MapperSettings", 0, "", why);
  return settings;
}

}  // namespace

class Mapper::Impl {
 public:
  explicit Impl(const MapperSettings& settings)
      : settings_(Validated(settings)),
        platform_(LoadPlatform(settings_.platform_file)),
        scene_scans_(CheckedOptions(settings_, platform_).localizer.scans_per_3d_scan),
        merge_(ExpectedStreams(settings_, *platform_.plugin.plugin)) {
    if (settings_.mode == MapperMode::kLive) worker_ = std::thread([this] { Work(); });
  }

  ~Impl() {
    {
      std::lock_guard<std::mutex> lock(work_mutex_);
      stop_ = true;
      abandon_ = true;  // what is still queued is dropped (Finish processes it)
    }
    work_ready_.notify_all();
    if (worker_.joinable()) worker_.join();
  }

  void Add(api::Stream stream, double time_s, io::DatasetEvent event) {
    std::unique_lock<std::mutex> lock(add_mutex_);
    if (finished_) throw InputError("the mapper has finished: no data is accepted after Finish()");
    RethrowWorkerError();
    merge_.Push(stream, time_s, std::move(event));
    if (stream == api::Stream::kScan) ++scans_added_;
    newest_added_s_ = std::max(newest_added_s_, time_s);
    Release(false);
  }

  void Finish() {
    std::unique_lock<std::mutex> lock(add_mutex_);
    if (finished_) return;
    finished_ = true;
    Release(true);
    if (worker_.joinable()) {
      {
        std::lock_guard<std::mutex> work_lock(work_mutex_);
        stop_ = true;
      }
      work_ready_.notify_all();
      worker_.join();
      RethrowWorkerError();
    }
    std::lock_guard<std::mutex> process_lock(process_mutex_);
    if (!mapper_) Build();
    mapper_->Finish();
    CollectPoses();
  }

  void SetPoseCallback(std::function<void(const MapperPose&)> callback) {
    std::lock_guard<std::mutex> lock(process_mutex_);
    callback_ = std::move(callback);
  }

  std::vector<MapperPose> Poses() const {
    std::lock_guard<std::mutex> lock(poses_mutex_);
    return poses_;
  }
  std::vector<StampedPose> Trajectory() const {
    std::lock_guard<std::mutex> lock(process_mutex_);
    if (!mapper_) return {};
    return mapper_->OptimizedTrajectory();
  }
  std::vector<Eigen::Vector3f> MapPoints(double voxel_m) const {
    if (!(voxel_m > 0.0)) throw InputError("MapPoints: voxel_m must be > 0, got " + std::to_string(voxel_m));
    std::lock_guard<std::mutex> lock(process_mutex_);
    if (!mapper_) return {};
    return mapper_->MapPoints(voxel_m);
  }

  MapperStatus Status() const {
    MapperStatus status;
    double newest_added_s = 0.0;
    {
      std::lock_guard<std::mutex> lock(add_mutex_);
      status.scans_added = scans_added_;
      status.events_waiting = merge_.size();
      newest_added_s = newest_added_s_;
    }
    {
      std::lock_guard<std::mutex> lock(work_mutex_);
      status.events_waiting += work_.size();
    }
    std::lock_guard<std::mutex> lock(process_mutex_);
    if (!mapper_) {
      status.events_waiting += held_.size();
      return status;
    }
    const pipeline::LocalizerStats& localizer = mapper_->localizer_stats();
    status.scans_processed = localizer.scans;
    status.scans_matched = localizer.scans_matched;
    const pipeline::MapperStats stats = mapper_->stats();
    status.key_scans = stats.key_scans;
    status.submaps = stats.submaps;
    status.loop_closures = stats.loop_closures;
    status.lag_s = newest_processed_s_ ? std::max(0.0, newest_added_s - *newest_processed_s_) : 0.0;
    return status;
  }

  std::string PayloadName() const { return platform_.plugin.plugin->Name(); }

 private:
  // Moves the merge's final events on (flush: all of them): processed here
  // (kSynchronous) or queued for the worker (kLive). Holds add_mutex_.
  void Release(bool flush) {
    while (std::optional<io::DatasetEvent> event = merge_.Pop(flush)) {
      if (settings_.mode == MapperMode::kSynchronous) {
        std::lock_guard<std::mutex> lock(process_mutex_);
        Process(std::move(*event));
        continue;
      }
      {
        std::lock_guard<std::mutex> lock(work_mutex_);
        work_.push_back(std::move(*event));
      }
      work_ready_.notify_one();
    }
  }

  // kLive: processes queued events until stopped and the queue is empty.
  void Work() {
    for (;;) {
      io::DatasetEvent event;
      {
        std::unique_lock<std::mutex> lock(work_mutex_);
        work_ready_.wait(lock, [this] { return stop_ || !work_.empty(); });
        if (work_.empty() || abandon_) return;  // stopped
        event = std::move(work_.front());
        work_.pop_front();
      }
      try {
        std::lock_guard<std::mutex> lock(process_mutex_);
        Process(std::move(event));
      } catch (...) {
        std::lock_guard<std::mutex> lock(work_mutex_);
        if (!worker_error_) worker_error_ = std::current_exception();
      }
    }
  }

  void RethrowWorkerError() {
    std::lock_guard<std::mutex> lock(work_mutex_);
    if (worker_error_) std::rethrow_exception(std::exchange(worker_error_, nullptr));
  }

  // Holds process_mutex_. Until the first 3D scan's scans have arrived the
  // events are held: they size the map's voxel (pipeline::SceneVoxel, as
  // `unimap run` does from the dataset's first scans), then the mapper is
  // built and they are processed in order.
  void Process(io::DatasetEvent event) {
    if (mapper_) {
      ProcessBuilt(std::move(event));
      return;
    }
    if (std::holds_alternative<io::ScanRecord>(event)) ++held_scans_;
    held_.push_back(std::move(event));
    if (held_scans_ >= scene_scans_) Build();
  }

  // Holds process_mutex_: builds the mapper for the held scans' scene, then
  // processes the held events in order. Throws ConfigError when the
  // platform's `mapper:` section is invalid at the scene's voxel (the events
  // stay held; the next call measures the same first scans again).
  void Build() {
    std::vector<io::ScanRecord> scans;
    for (const io::DatasetEvent& event : held_) {
      const auto* scan = std::get_if<io::ScanRecord>(&event);
      if (scan != nullptr && static_cast<int>(scans.size()) < scene_scans_) scans.push_back(*scan);
    }
    const pipeline::SceneScale scene = pipeline::MeasureSceneScale(scans);
    scans.clear();
    mapper_.emplace(OptionsFor(settings_, platform_, scene), platform_.plugin.plugin);
    while (!held_.empty()) {
      io::DatasetEvent event = std::move(held_.front());
      held_.pop_front();
      ProcessBuilt(std::move(event));
    }
  }

  // Holds process_mutex_.
  void ProcessBuilt(io::DatasetEvent event) {
    if (auto* imu = std::get_if<ImuSample>(&event)) {
      mapper_->AddImu(*imu);
    } else if (auto* encoder = std::get_if<EncoderSample>(&event)) {
      mapper_->AddEncoder(*encoder);
    } else if (auto* odometry = std::get_if<OdometrySample>(&event)) {
      mapper_->AddOdometry(*odometry);
    } else {
      io::ScanRecord& scan = std::get<io::ScanRecord>(event);
      newest_processed_s_ = io::ScanEndTime(scan);
      mapper_->AddScan(std::move(scan));
    }
    CollectPoses();
  }

  // Holds process_mutex_.
  void CollectPoses() {
    for (const pipeline::ScanPose& pose : mapper_->TakePoses()) {
      const MapperPose out{pose.time_s, pose.T_map_body, pose.matched, pose.points};
      {
        std::lock_guard<std::mutex> lock(poses_mutex_);
        poses_.push_back(out);
      }
      if (callback_) callback_(out);
    }
  }

  const MapperSettings settings_;
  const Platform platform_;                 // holds the plugin's library while mapper_ uses it
  const int scene_scans_;                   // scans that size the map's voxel (the first 3D scan's)
  std::optional<pipeline::Mapper> mapper_;  // guarded by process_mutex_; built by Build()
  std::deque<io::DatasetEvent> held_;       // guarded by process_mutex_: events before Build()
  int held_scans_ = 0;                      // guarded by process_mutex_: scans among them

  mutable std::mutex add_mutex_;  // guards the merge and the counters below
  api::EventMerge merge_;
  std::size_t scans_added_ = 0;
  double newest_added_s_ = 0.0;
  bool finished_ = false;

  mutable std::mutex process_mutex_;  // guards mapper_, the callback and newest_processed_s_
  std::function<void(const MapperPose&)> callback_;
  std::optional<double> newest_processed_s_;

  mutable std::mutex poses_mutex_;
  std::vector<MapperPose> poses_;

  mutable std::mutex work_mutex_;  // kLive: guards the queue, stop_ and worker_error_
  std::condition_variable work_ready_;
  std::deque<io::DatasetEvent> work_;
  bool stop_ = false;     // the worker returns once the queue is empty
  bool abandon_ = false;  // ... or at once (destruction)
  std::exception_ptr worker_error_;
  std::thread worker_;  // last: started once everything above exists
};

Mapper::Mapper(const MapperSettings& settings) : impl_(std::make_unique<Impl>(settings)) {}
Mapper::Mapper(const std::string& platform_file) : Mapper(MapperSettings{platform_file}) {}
Mapper::~Mapper() = default;

void Mapper::AddImu(const ImuSample& sample) { impl_->Add(api::Stream::kImu, sample.time_s, sample); }
void Mapper::AddEncoder(const EncoderSample& sample) { impl_->Add(api::Stream::kEncoder, sample.time_s, sample); }
void Mapper::AddOdometry(const OdometrySample& sample) { impl_->Add(api::Stream::kOdometry, sample.time_s, sample); }
void Mapper::AddScan(const RawScan& scan) { impl_->Add(api::Stream::kScan, scan.end_time_s, io::ScanRecord(scan)); }
void Mapper::AddScan(const LineScan& scan) {
  io::ScanRecord record(scan);
  const double end_time_s = io::ScanEndTime(record);
  impl_->Add(api::Stream::kScan, end_time_s, std::move(record));
}
void Mapper::SetPoseCallback(std::function<void(const MapperPose&)> callback) {
  impl_->SetPoseCallback(std::move(callback));
}
void Mapper::Finish() { impl_->Finish(); }
std::vector<MapperPose> Mapper::Poses() const { return impl_->Poses(); }
std::vector<StampedPose> Mapper::Trajectory() const { return impl_->Trajectory(); }
std::vector<Eigen::Vector3f> Mapper::MapPoints(double voxel_m) const { return impl_->MapPoints(voxel_m); }
void Mapper::WriteMap(const std::string& path, double voxel_m) const {
  const std::filesystem::path file(path);
  const std::string extension = file.extension().string();
  if (extension != ".ply" && extension != ".pcd") {
    throw InputError(path + ": the map is written as .ply or .pcd, not '" + extension + "'");
  }
  const std::vector<Eigen::Vector3f> points = MapPoints(voxel_m);
  if (extension == ".ply") {
    io::WritePly(file, points);
  } else {
    io::WritePcdXyz(file, points);
  }
}
MapperStatus Mapper::Status() const { return impl_->Status(); }
std::string Mapper::PayloadName() const { return impl_->PayloadName(); }

}  // namespace unimap
