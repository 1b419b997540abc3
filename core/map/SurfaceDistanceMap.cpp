#include "map/SurfaceDistanceMap.hpp"

#include <chrono>
#include <string>
#include <utility>

#include "unimap/Errors.hpp"

namespace unimap::map {
namespace {

DistanceMapOptions Checked(const DistanceMapOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw ConfigError("", 0, "distance_map", why);
  return options;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SurfaceDistanceMap::SurfaceDistanceMap(const DistanceMapOptions& options)
    : options_(Checked(options)),
      layer_(options_),
      snapshot_(std::make_shared<const DistanceField>(static_cast<float>(options_.clamp_distance_m))),
      worker_([this] { Run(); }) {}

SurfaceDistanceMap::~SurfaceDistanceMap() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  worker_.join();
}

void SurfaceDistanceMap::InsertScan(std::vector<Eigen::Vector3f> points_map, const Eigen::Vector3f& sensor_origin_map) {
  if (!sensor_origin_map.allFinite()) throw InputError("SurfaceDistanceMap: sensor origin must be finite");
  Job job;
  job.sensor_map = sensor_origin_map;
  // Returns beyond the insertion range mark nothing (as the octree maps cut their rays).
  const float max_range_sq = static_cast<float>(options_.max_insert_range_m * options_.max_insert_range_m);
  job.points_map.reserve(points_map.size());
  for (const Eigen::Vector3f& p : points_map) {
    if ((p - sensor_origin_map).squaredNorm() <= max_range_sq) job.points_map.push_back(p);
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(std::move(job));
    ++queued_;
  }
  wake_.notify_one();
}

void SurfaceDistanceMap::UpdateSensorPosition(const Eigen::Vector3f& sensor_map) {
  if (!sensor_map.allFinite()) throw InputError("SurfaceDistanceMap: sensor position must be finite");
  std::lock_guard<std::mutex> lock(mutex_);
  center_map_ = sensor_map;
}

void SurfaceDistanceMap::EnableDistances() {
  Job job;
  job.enable_distances = true;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(std::move(job));
    ++queued_;
  }
  wake_.notify_one();
}

std::shared_ptr<const DistanceField> SurfaceDistanceMap::Snapshot() const {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return snapshot_;
}

void SurfaceDistanceMap::WaitForUpdates() {
  std::unique_lock<std::mutex> lock(mutex_);
  idle_.wait(lock, [this] { return done_ == queued_; });
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

std::vector<Eigen::Vector3f> SurfaceDistanceMap::SurfaceMeans() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    idle_.wait(lock, [this] { return done_ == queued_; });
  }
  std::lock_guard<std::mutex> layer_lock(layer_mutex_);
  return layer_.SurfaceMeans();
}

MapUpdateTimes SurfaceDistanceMap::UpdateTimes() const {
  const SurfaceDistanceMapStats stats = Stats();
  MapUpdateTimes times;
  times.surface_s = stats.layer.surface_s;
  times.distance_s = stats.layer.distance_s;
  times.export_s = stats.layer.export_s;
  return times;
}

SurfaceDistanceMapStats SurfaceDistanceMap::Stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stats_;
}

void SurfaceDistanceMap::Run() {
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stop_ || !queue_.empty(); });
    if (stop_) return;
    std::vector<Job> jobs;
    jobs.swap(queue_);
    Eigen::Vector3f center = center_map_;
    lock.unlock();
    std::exception_ptr error;
    SurfaceDistanceMapStats stats;
    try {
      std::lock_guard<std::mutex> layer_lock(layer_mutex_);
      Process(jobs, &center, &stats);
    } catch (const std::exception&) {
      error = std::current_exception();
    }
    lock.lock();
    if (error) error_ = error;
    center_map_ = center;
    stats_.scans_inserted += stats.scans_inserted;
    stats_.exports += stats.exports;
    stats_.insert_s += stats.insert_s;
    stats_.layer = stats.layer;
    if (stats.exports > 0) stats_.field_bytes = stats.field_bytes;
    done_ += jobs.size();
    idle_.notify_all();
  }
}

void SurfaceDistanceMap::Process(const std::vector<Job>& jobs, Eigen::Vector3f* center_map,
                                 SurfaceDistanceMapStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  bool changed = false;
  for (const Job& job : jobs) {
    if (job.enable_distances) {
      changed = changed || !layer_.distances();
      layer_.EnableDistances();
      continue;
    }
    layer_.Insert(job.points_map, job.sensor_map);
    *center_map = job.sensor_map;
    changed = true;
    ++stats->scans_inserted;
  }
  stats->insert_s += SecondsSince(start);
  stats->layer = layer_.counts();
  sequence_ += jobs.size();
  if (!changed || !layer_.distances()) return;
  std::shared_ptr<const DistanceField> field = layer_.Export(*center_map, options_.max_range_m, sequence_);
  stats->layer = layer_.counts();
  ++stats->exports;
  stats->field_bytes = field->MemoryBytes();
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  std::swap(snapshot_, field);  // the previous field is released outside the lock
}

}  // namespace unimap::map
