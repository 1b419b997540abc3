#include "map/SubmapManager.hpp"

#include "unimap/Errors.hpp"

namespace unimap::map {
namespace {

SubmapOptions Checked(const SubmapOptions& options) {
  std::string why;
  if (!options.IsValid(&why)) throw ConfigError("", 0, "", "submap options: " + why);
  return options;
}

}  // namespace

SubmapManager::SubmapManager(const SubmapOptions& options)
    : options_(Checked(options)),
      empty_(std::make_shared<DistanceField>(static_cast<float>(options_.map.clamp_distance_m))) {}

SubmapManager::~SubmapManager() = default;

std::shared_ptr<const DistanceField> SubmapManager::Snapshot() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return live_.empty() ? empty_ : live_.front()->distance_map().Snapshot();
}

void SubmapManager::InsertScan(std::vector<Eigen::Vector3f> points_local, const Eigen::Vector3f& sensor_origin_local) {
  if (!sensor_origin_local.allFinite()) throw InputError("submap insertion: sensor origin is not finite");
  std::lock_guard<std::mutex> lock(mutex_);
  SubmapInsertion insertion;
  if (live_.empty()) {
    live_.push_back(std::make_unique<Submap>(next_id_++, sensor_origin_local.cast<double>(), options_.map));
    insertion.created_ids.push_back(live_.back()->id());
    insertion.created_T_local_submaps.push_back(live_.back()->T_local_submap());
  }
  // Every live submap receives the scan; the last one takes the points by move.
  for (std::size_t i = 0; i < live_.size(); ++i) {
    Submap& submap = *live_[i];
    if (i + 1 < live_.size()) {
      submap.Insert(points_local, sensor_origin_local);
    } else {
      submap.Insert(std::move(points_local), sensor_origin_local);
    }
    insertion.submap_ids.push_back(submap.id());
    insertion.T_local_submaps.push_back(submap.T_local_submap());
  }
  const int half = options_.scans_3d_per_submap / 2;
  if (live_.front()->scans_3d() >= options_.scans_3d_per_submap) {
    retired_.push_back(live_.front()->Retire());
    retired_times_ += retired_.back().update_times;
    live_.pop_front();
    // The growing submap becomes the matching one: its distance transform
    // starts now (built over its box in one go).
    if (!live_.empty()) live_.front()->distance_map().EnableDistances();
  }
  if (live_.empty() || live_.back()->scans_3d() >= half) {
    // A growing submap keeps only its octree until it becomes the matching one.
    DistanceMapOptions growing = options_.map;
    growing.compute_distances = live_.empty() && options_.map.compute_distances;
    live_.push_back(std::make_unique<Submap>(next_id_++, sensor_origin_local.cast<double>(), growing));
    insertion.created_ids.push_back(live_.back()->id());
    insertion.created_T_local_submaps.push_back(live_.back()->T_local_submap());
  }
  last_ = std::move(insertion);
}

void SubmapManager::UpdateSensorPosition(const Eigen::Vector3f& sensor_local) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& submap : live_) submap->distance_map().UpdateSensorPosition(sensor_local);
}

void SubmapManager::WaitForUpdates() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& submap : live_) submap->distance_map().WaitForUpdates();
}

MapUpdateTimes SubmapManager::UpdateTimes() const {
  std::lock_guard<std::mutex> lock(mutex_);
  MapUpdateTimes times = retired_times_;
  for (const auto& submap : live_) times += submap->distance_map().UpdateTimes();
  return times;
}

SubmapInsertion SubmapManager::last_insertion() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return last_;
}

std::vector<RetiredSubmap> SubmapManager::TakeRetired() {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<RetiredSubmap> out;
  out.swap(retired_);
  return out;
}

std::size_t SubmapManager::live_count() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return live_.size();
}

int SubmapManager::started_count() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return next_id_;
}

}  // namespace unimap::map
