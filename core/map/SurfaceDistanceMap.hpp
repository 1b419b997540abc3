#pragma once
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "map/DistanceMapOptions.hpp"
#include "map/ScanMap.hpp"
#include "map/SurfaceDistanceLayer.hpp"

namespace unimap::map {

// Counters of a SurfaceDistanceMap (for run.json and benchmarks).
struct SurfaceDistanceMapStats {
  SurfaceDistanceCounts layer;       // the layer's counters
  std::uint64_t scans_inserted = 0;  // InsertScan calls integrated
  std::uint64_t exports = 0;         // fields published
  std::size_t field_bytes = 0;       // memory of the published field
  double insert_s = 0.0;             // time integrating scans (surfaces and distances, wall)
};

// The odometry map of a submap (docs/design.md 1.4): a
// SurfaceDistanceLayer updated on a background thread. InsertScan queues a
// scan and returns; the worker integrates queued scans in order and
// publishes a new immutable DistanceField (the blocks within
// options.max_range_m of the latest sensor position, sharing unchanged blocks
// with the previous one) that Snapshot() hands out without waiting. With
// options.compute_distances false only the surface is kept until
// EnableDistances(). Distances are unsigned, to the sub-voxel surface
// elements, exact up to options.clamp_distance_m. Returns farther than
// options.max_insert_range_m from the sensor are not inserted. Rays carve
// free space only through blocks holding an occupied voxel
// (DistanceMapOptions::raycast_free_space, clear_occupied_only). Thread-safe.
class SurfaceDistanceMap : public ScanMap {
 public:
  // Throws ConfigError when the options are invalid.
  explicit SurfaceDistanceMap(const DistanceMapOptions& options);
  // Stops the worker; scans still queued are dropped.
  ~SurfaceDistanceMap() override;
  SurfaceDistanceMap(const SurfaceDistanceMap&) = delete;
  SurfaceDistanceMap& operator=(const SurfaceDistanceMap&) = delete;

  // Queues a scan (points and sensor origin in the map frame). A non-finite
  // origin throws InputError; non-finite points are dropped and counted.
  void InsertScan(std::vector<Eigen::Vector3f> points_map, const Eigen::Vector3f& sensor_origin_map) override;
  // Moves the published box's centre (the next publication uses it).
  void UpdateSensorPosition(const Eigen::Vector3f& sensor_map) override;
  // Turns the distances on (all elements propagated once, then published).
  void EnableDistances();

  std::shared_ptr<const DistanceField> Snapshot() const override;
  void WaitForUpdates() override;
  MapUpdateTimes UpdateTimes() const override;

  // The mean of the returns in each occupied voxel (waits for queued scans
  // first; SurfaceDistanceLayer::SurfaceMeans).
  std::vector<Eigen::Vector3f> SurfaceMeans();
  SurfaceDistanceMapStats Stats() const;
  const DistanceMapOptions& options() const { return options_; }

 private:
  struct Job {
    std::vector<Eigen::Vector3f> points_map;
    Eigen::Vector3f sensor_map = Eigen::Vector3f::Zero();
    bool enable_distances = false;
  };
  void Run();
  // Integrates a batch of jobs (under layer_mutex_) and publishes when
  // something changed; *center_map is the box centre, moved to the last
  // scan's sensor; *stats receives this batch's counts.
  void Process(const std::vector<Job>& jobs, Eigen::Vector3f* center_map, SurfaceDistanceMapStats* stats);

  const DistanceMapOptions options_;
  mutable std::mutex layer_mutex_;  // held by the worker while it updates the layer
  SurfaceDistanceLayer layer_;
  std::uint64_t sequence_ = 0;

  mutable std::mutex snapshot_mutex_;  // held only to copy the pointer
  std::shared_ptr<const DistanceField> snapshot_;

  mutable std::mutex mutex_;  // guards everything below
  Eigen::Vector3f center_map_ = Eigen::Vector3f::Zero();
  std::condition_variable wake_;
  std::condition_variable idle_;
  std::vector<Job> queue_;
  std::uint64_t queued_ = 0;
  std::uint64_t done_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
  SurfaceDistanceMapStats stats_;

  std::thread worker_;  // last: started once everything above exists
};

}  // namespace unimap::map
