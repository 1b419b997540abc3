#pragma once
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include <Eigen/Core>

#include "map/DistanceField.hpp"
#include "map/DistanceMapOptions.hpp"
#include "map/DistanceMapStats.hpp"
#include "map/FieldBoxPlanner.hpp"
#include "map/KeyBox.hpp"
#include "map/ScanMap.hpp"

namespace octomap {
class OcTree;
}

namespace unimap::map {

class EdtRegion;
class OccupancyTree;

// Occupancy octree plus an incremental distance transform (DynamicEDT3D,
// driven by OctoMap's change detection) in a box around the sensor. Scans are
// queued and integrated on a background thread; each update that can change
// distances publishes a new immutable DistanceField (a batch that only moves
// the sensor inside the box keeps the last one, with its sequence) that
// readers take with Snapshot() without ever waiting for an update in
// progress. The box follows the sensor: when it moves farther than
// recenter_fraction * max_range_m from the box centre, the transform is
// rebuilt around it (the previous snapshot stays valid until the new one is
// published). The box is clipped to the occupied voxels near the
// sensor (see FieldBoxPlanner). Requests queued while an update runs are
// integrated together, with one distance update for the batch. With
// options.subvoxel_surfaces, distances are to the surface the returns put
// inside each occupied voxel (SurfacePoints), signed behind it, instead of
// to the voxel centres; the published field reads magnitudes. All methods
// are thread-safe.
class DistanceMap : public ScanMap {
 public:
  // An empty map. Throws ConfigError when the options are invalid.
  explicit DistanceMap(const DistanceMapOptions& options);
  // A prior map from an octree (its resolution replaces options.resolution_m),
  // boxed around center_map. The first field is built in the background.
  static std::unique_ptr<DistanceMap> FromOctree(std::unique_ptr<octomap::OcTree> tree,
                                                 const DistanceMapOptions& options, const Eigen::Vector3f& center_map);
  // A prior map from an OctoMap .bt file. Throws InputError when it cannot be read.
  static std::unique_ptr<DistanceMap> LoadBt(const std::filesystem::path& path, const DistanceMapOptions& options,
                                             const Eigen::Vector3f& center_map);
  // A prior map whose occupied voxels are those holding a point (map frame).
  static std::unique_ptr<DistanceMap> FromPoints(const std::vector<Eigen::Vector3f>& points_map,
                                                 const DistanceMapOptions& options, const Eigen::Vector3f& center_map);
  // Stops the background thread; queued scans not yet integrated are dropped.
  ~DistanceMap() override;
  DistanceMap(const DistanceMap&) = delete;
  DistanceMap& operator=(const DistanceMap&) = delete;

  // Queues a scan (points and sensor origin in the map frame) and returns at
  // once. Non-finite points are dropped and counted; a non-finite origin or
  // one outside the octree's key range throws InputError.
  void InsertScan(std::vector<Eigen::Vector3f> points_map, const Eigen::Vector3f& sensor_origin_map) override;
  // Tells the box-follows-sensor policy where the sensor is (for localisation
  // in a prior map, where nothing is inserted). Same errors as InsertScan.
  void UpdateSensorPosition(const Eigen::Vector3f& sensor_map) override;
  // Starts the distance transform of a map made with compute_distances =
  // false: the next update builds it over the box around the last sensor
  // position (WaitForUpdates() waits for it). No effect when already on.
  void EnableDistances();
  // Moves the box centre to center_map regardless of the policy.
  void SetCenter(const Eigen::Vector3f& center_map);

  // The latest published field (never null; empty until the first update).
  std::shared_ptr<const DistanceField> Snapshot() const override;
  // Blocks until everything queued so far is published. Rethrows (once) an
  // exception a background update threw since the last call.
  void WaitForUpdates() override;

  // Centres of all occupied voxels (waits while an update holds the octree).
  std::vector<Eigen::Vector3f> OccupiedVoxelCenters() const;
  // Calls visit with the octree under the map's lock (e.g. to write a .bt).
  // With clear_occupied_only the tree holds only voxels that were ever hit:
  // free space reads as unknown.
  void VisitOctree(const std::function<void(const octomap::OcTree&)>& visit) const;
  DistanceMapStats Stats() const;
  const DistanceMapOptions& options() const { return options_; }

  // Test hook, run on the background thread after a field is computed and
  // before it is published (pass an empty function to remove it).
  void SetUpdateHookForTesting(std::function<void()> hook);

 private:
  // One queued request.
  struct Job {
    std::vector<Eigen::Vector3f> points_map;               // scan to insert (empty: position only)
    Eigen::Vector3f sensor_map = Eigen::Vector3f::Zero();  // sensor position / forced centre
    bool force_center = false;                             // sensor_map is a forced box centre
    bool enable_distances = false;                         // turns the distance transform on (no position)
  };

  DistanceMap(std::unique_ptr<OccupancyTree> tree, const DistanceMapOptions& options);
  // options with resolution_m set; throws ConfigError when they are invalid.
  static DistanceMapOptions ValidOptions(DistanceMapOptions options, double resolution_m);
  void CheckPosition(const Eigen::Vector3f& p_map, const char* what) const;
  void Enqueue(Job job);
  void WorkerLoop();
  // Integrates jobs into the octree and the EDT; returns the field to publish
  // (null when the batch only moved the sensor inside the box).
  std::shared_ptr<const DistanceField> ProcessBatch(std::vector<Job>& jobs);
  // Rebuilds the EDT over the current sensor box; returns false when empty.
  bool RebuildRegion();
  void Publish(std::shared_ptr<const DistanceField> field);

  const DistanceMapOptions options_;
  double half_range_m_;  // coordinates must stay within this (octree key range)

  // Octree and EDT state, touched by the worker (and readers) under octree_mutex_.
  mutable std::mutex octree_mutex_;
  std::unique_ptr<OccupancyTree> tree_;
  FieldBoxPlanner planner_;
  std::unique_ptr<EdtRegion> region_;
  bool has_center_ = false;
  bool distances_on_ = true;  // options_.compute_distances until EnableDistances()
  Eigen::Vector3i center_key_ = Eigen::Vector3i::Zero();
  KeyBox sensor_box_;
  KeyBox occupied_;  // occupied voxels of sensor_box_ (grown conservatively)
  std::uint64_t sequence_ = 0;

  mutable std::mutex snapshot_mutex_;  // held only to copy the pointer
  std::shared_ptr<const DistanceField> snapshot_;

  mutable std::mutex stats_mutex_;
  DistanceMapStats stats_;

  mutable std::mutex queue_mutex_;
  std::condition_variable work_cv_;
  std::condition_variable idle_cv_;
  std::vector<Job> queue_;
  std::uint64_t submitted_ = 0;
  std::uint64_t completed_ = 0;
  bool stop_ = false;
  std::exception_ptr error_;
  std::function<void()> hook_;

  std::thread worker_;  // last: started once everything above exists
};

}  // namespace unimap::map
