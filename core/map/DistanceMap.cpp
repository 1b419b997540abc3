#include "map/DistanceMap.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <utility>

#include <octomap/OcTree.h>

#include "map/EdtRegion.hpp"
#include "map/OccupancyTree.hpp"
#include "unimap/Errors.hpp"

namespace unimap::map {

namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point from, Clock::time_point to) {
  return std::chrono::duration<double>(to - from).count();
}

}  // namespace

DistanceMapOptions DistanceMap::ValidOptions(DistanceMapOptions options, double resolution_m) {
  options.resolution_m = resolution_m;
  std::string why;
  if (!options.IsValid(&why)) throw ConfigError("", 0, "distance_map", why);
  return options;
}

DistanceMap::DistanceMap(const DistanceMapOptions& options)
    : DistanceMap(std::make_unique<OccupancyTree>(ValidOptions(options, options.resolution_m)), options) {}

DistanceMap::DistanceMap(std::unique_ptr<OccupancyTree> tree, const DistanceMapOptions& options)
    : options_(ValidOptions(options, tree->resolution_m())),
      half_range_m_(tree->HalfRangeM()),
      tree_(std::move(tree)),
      planner_(options_, options_.resolution_m),
      snapshot_(std::make_shared<const DistanceField>(static_cast<float>(options_.clamp_distance_m))) {
  distances_on_ = options_.compute_distances;
  worker_ = std::thread([this] { WorkerLoop(); });
}

DistanceMap::~DistanceMap() {
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    stop_ = true;
  }
  work_cv_.notify_all();
  worker_.join();
}

void DistanceMap::CheckPosition(const Eigen::Vector3f& p_map, const char* what) const {
  const double reach = std::max(options_.max_range_m, options_.max_insert_range_m);
  if (!p_map.allFinite() || static_cast<double>(p_map.cwiseAbs().maxCoeff()) + reach >= half_range_m_) {
    throw InputError(std::string("DistanceMap: ") + what + " must be finite and within the octree's key range");
  }
}

void DistanceMap::InsertScan(std::vector<Eigen::Vector3f> points_map, const Eigen::Vector3f& sensor_origin_map) {
  CheckPosition(sensor_origin_map, "sensor origin");
  const std::size_t before = points_map.size();
  points_map.erase(
      std::remove_if(points_map.begin(), points_map.end(), [](const Eigen::Vector3f& p) { return !p.allFinite(); }),
      points_map.end());
  if (points_map.size() != before) {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    stats_.points_skipped += before - points_map.size();
  }
  Job job;
  job.points_map = std::move(points_map);
  job.sensor_map = sensor_origin_map;
  Enqueue(std::move(job));
}

void DistanceMap::UpdateSensorPosition(const Eigen::Vector3f& sensor_map) {
  CheckPosition(sensor_map, "sensor position");
  Job job;
  job.sensor_map = sensor_map;
  Enqueue(std::move(job));
}

void DistanceMap::EnableDistances() {
  Job job;
  job.enable_distances = true;
  Enqueue(std::move(job));
}

void DistanceMap::SetCenter(const Eigen::Vector3f& center_map) {
  CheckPosition(center_map, "box centre");
  Job job;
  job.sensor_map = center_map;
  job.force_center = true;
  Enqueue(std::move(job));
}

void DistanceMap::Enqueue(Job job) {
  {
    std::lock_guard<std::mutex> lock(queue_mutex_);
    queue_.push_back(std::move(job));
    ++submitted_;
  }
  work_cv_.notify_one();
}

std::shared_ptr<const DistanceField> DistanceMap::Snapshot() const {
  std::lock_guard<std::mutex> lock(snapshot_mutex_);
  return snapshot_;
}

void DistanceMap::Publish(std::shared_ptr<const DistanceField> field) {
  {
    std::lock_guard<std::mutex> lock(snapshot_mutex_);
    std::swap(snapshot_, field);
  }
  // The previous field (now in `field`) is released outside the lock.
}

void DistanceMap::WaitForUpdates() {
  std::unique_lock<std::mutex> lock(queue_mutex_);
  idle_cv_.wait(lock, [this] { return completed_ == submitted_; });
  if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
}

std::vector<Eigen::Vector3f> DistanceMap::OccupiedVoxelCenters() const {
  std::lock_guard<std::mutex> lock(octree_mutex_);
  return tree_->OccupiedVoxelCenters();
}

void DistanceMap::VisitOctree(const std::function<void(const octomap::OcTree&)>& visit) const {
  std::lock_guard<std::mutex> lock(octree_mutex_);
  visit(tree_->tree());
}

DistanceMapStats DistanceMap::Stats() const {
  DistanceMapStats stats;
  {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    stats = stats_;
  }
  std::lock_guard<std::mutex> lock(queue_mutex_);
  stats.pending_jobs = submitted_ - completed_;
  return stats;
}

void DistanceMap::SetUpdateHookForTesting(std::function<void()> hook) {
  std::lock_guard<std::mutex> lock(queue_mutex_);
  hook_ = std::move(hook);
}

void DistanceMap::WorkerLoop() {
  for (;;) {
    std::vector<Job> jobs;
    std::function<void()> hook;
    {
      std::unique_lock<std::mutex> lock(queue_mutex_);
      work_cv_.wait(lock, [this] { return stop_ || !queue_.empty(); });
      if (stop_) return;
      jobs.swap(queue_);
      hook = hook_;
    }
    try {
      std::shared_ptr<const DistanceField> field = ProcessBatch(jobs);
      if (hook) hook();
      if (field) Publish(std::move(field));  // null: nothing changed, the published field stays
    } catch (const std::exception&) {
      {
        std::lock_guard<std::mutex> lock(octree_mutex_);
        region_.reset();  // start over around the next sensor position
        has_center_ = false;
      }
      {
        std::lock_guard<std::mutex> lock(stats_mutex_);
        ++stats_.failed_updates;
      }
      std::lock_guard<std::mutex> lock(queue_mutex_);
      error_ = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(queue_mutex_);
      completed_ += jobs.size();
    }
    idle_cv_.notify_all();
  }
}

std::shared_ptr<const DistanceField> DistanceMap::ProcessBatch(std::vector<Job>& jobs) {
  std::unique_lock<std::mutex> lock(octree_mutex_);
  const Clock::time_point start = Clock::now();
  KeyBox endpoints;
  bool recenter = false;
  bool changed = false;  // points inserted or distances enabled: the field may change
  DistanceMapStats counts;
  for (Job& job : jobs) {
    if (job.enable_distances) {
      recenter = recenter || (!distances_on_ && has_center_);
      distances_on_ = true;
      changed = true;
      continue;
    }
    if (!job.points_map.empty()) {
      endpoints.Extend(tree_->Insert(job.points_map, job.sensor_map));
      changed = true;
      ++counts.scans_inserted;
      counts.points_inserted += job.points_map.size();
    }
    const Eigen::Vector3i sensor_key = tree_->KeyOf(job.sensor_map);
    if (job.force_center || !has_center_ ||
        (options_.follow_sensor && planner_.NeedsRecenter(center_key_, sensor_key))) {
      center_key_ = sensor_key;
      has_center_ = true;
      recenter = true;
    }
  }
  sequence_ += jobs.size();
  const Clock::time_point inserted = Clock::now();
  if (!changed && !recenter) {
    // Only sensor positions inside the current box (e.g. localisation in a
    // fixed map): nothing can have changed, the last field stays published.
    return nullptr;
  }

  bool rebuilt = false;
  if (!distances_on_) {
    // A growing submap: the octree only (the changes are not consumed).
  } else if (recenter) {
    sensor_box_ = planner_.SensorBox(center_key_);
    occupied_ = tree_->OccupiedExtent(sensor_box_);
    rebuilt = RebuildRegion();
  } else {
    const KeyBox grown = planner_.GrownOccupied(occupied_, endpoints, sensor_box_);
    if (grown != occupied_) {
      occupied_ = grown;
      rebuilt = RebuildRegion();
    } else if (region_ != nullptr) {
      region_->Update();
      ++counts.incremental_updates;
    }
  }
  if (region_ == nullptr) tree_->tree().resetChangeDetection();  // nothing consumes them
  if (rebuilt) ++counts.rebuilds;
  const Clock::time_point updated = Clock::now();
  const EdtRegion* region = region_.get();
  const SurfacePoints* surfaces = tree_->surfaces();
  lock.unlock();  // only this thread touches region_ and the surfaces from here on

  std::shared_ptr<const DistanceField> field =
      region != nullptr
          ? region->Export(sequence_, surfaces, options_.cell_planes)
          : std::make_shared<const DistanceField>(static_cast<float>(options_.clamp_distance_m), sequence_);
  const Clock::time_point exported = Clock::now();

  std::lock_guard<std::mutex> stats_lock(stats_mutex_);
  stats_.scans_inserted += counts.scans_inserted;
  stats_.points_inserted += counts.points_inserted;
  stats_.incremental_updates += counts.incremental_updates;
  stats_.rebuilds += counts.rebuilds;
  stats_.edt_cells = region != nullptr ? region->CellCount() : 0;
  stats_.field_bytes = field->MemoryBytes();
  stats_.surface_voxels = surfaces != nullptr ? surfaces->size() : 0;
  stats_.surface_bytes = surfaces != nullptr ? surfaces->MemoryBytes() : 0;
  stats_.last_insert_s = Seconds(start, inserted);
  stats_.last_edt_s = Seconds(inserted, updated);
  stats_.last_export_s = Seconds(updated, exported);
  return field;
}

bool DistanceMap::RebuildRegion() {
  bool shrunk = false;
  const KeyBox field_box = planner_.FieldBox(occupied_, sensor_box_, center_key_, &shrunk);
  if (shrunk) {
    std::lock_guard<std::mutex> stats_lock(stats_mutex_);
    ++stats_.budget_shrinks;
  }
  if (field_box.IsEmpty()) {
    region_.reset();
    return false;
  }
  if (region_ != nullptr && region_->box() == field_box) {
    region_->Update();
    std::lock_guard<std::mutex> stats_lock(stats_mutex_);
    ++stats_.incremental_updates;
    return false;
  }
  region_.reset();  // free the old transform before allocating the new one
  region_ = std::make_unique<EdtRegion>(&tree_->tree(), field_box, static_cast<float>(options_.clamp_distance_m));
  return true;
}

}  // namespace unimap::map
