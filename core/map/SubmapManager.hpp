#pragma once
#include <deque>
#include <memory>
#include <mutex>
#include <vector>

#include "map/ScanMap.hpp"
#include "map/Submap.hpp"
#include "map/SubmapOptions.hpp"

namespace unimap::map {

// The submaps a 3D scan went into (the matching one first).
struct SubmapInsertion {
  std::vector<int> submap_ids;                             // ids of the receiving submaps
  std::vector<Eigen::Isometry3d> T_local_submaps;          // their frames, same order
  std::vector<int> created_ids;                            // submaps started by this insertion (before it,
                                                           // receiving it, or after it, for the next scans)
  std::vector<Eigen::Isometry3d> created_T_local_submaps;  // their frames, same order
};

// The paper's active submaps (docs/design.md 1.4, Cartographer's scheme): every 3D
// scan goes into the matching submap (the oldest live one, which the
// localiser matches against) and the growing one. When the newest submap has
// received M / 2 scans a new growing submap starts; when the matching one has
// received M it is retired (its live distance map dropped, its surface kept)
// and the growing one becomes the matching one. A new submap's frame is at
// the sensor position of the scan that starts it. Only the matching submap
// keeps a distance transform: a growing one updates its surface alone and
// builds its distances when it becomes the matching one. Thread-safe.
class SubmapManager : public ScanMap {
 public:
  // Throws ConfigError when the options are invalid.
  explicit SubmapManager(const SubmapOptions& options);
  ~SubmapManager() override;

  // The matching submap's field (an empty field before the first scan).
  std::shared_ptr<const DistanceField> Snapshot() const override;
  // Inserts into the live submaps, starting and retiring submaps as above.
  void InsertScan(std::vector<Eigen::Vector3f> points_local, const Eigen::Vector3f& sensor_origin_local) override;
  void UpdateSensorPosition(const Eigen::Vector3f& sensor_local) override;
  void WaitForUpdates() override;
  // Summed over every submap so far (live and retired).
  MapUpdateTimes UpdateTimes() const override;

  // Where the last InsertScan went.
  SubmapInsertion last_insertion() const;
  // Submaps retired since the last call, oldest first.
  std::vector<RetiredSubmap> TakeRetired();
  // Number of live submaps (0, 1 or 2) and of submaps ever started.
  std::size_t live_count() const;
  int started_count() const;

 private:
  const SubmapOptions options_;
  mutable std::mutex mutex_;
  std::deque<std::unique_ptr<Submap>> live_;  // oldest (matching) first
  std::vector<RetiredSubmap> retired_;
  SubmapInsertion last_;
  int next_id_ = 0;
  std::shared_ptr<const DistanceField> empty_;
  MapUpdateTimes retired_times_;  // of the submaps retired so far
};

}  // namespace unimap::map
