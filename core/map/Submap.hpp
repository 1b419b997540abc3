#pragma once
#include <memory>
#include <vector>

#include <Eigen/Geometry>

#include "map/CompactPoints.hpp"
#include "map/DistanceMapOptions.hpp"
#include "map/SurfaceDistanceMap.hpp"

namespace unimap::map {

// What a submap keeps once retired: no live distance map, only its surface
// (the mean of each occupied voxel's returns) in its own frame, for loop
// closure.
struct RetiredSubmap {
  int id = 0;                                                        // SubmapManager id
  Eigen::Isometry3d T_local_submap = Eigen::Isometry3d::Identity();  // frame at creation (local odometry frame)
  CompactPoints points_submap;  // surface points (the mean of each occupied voxel's returns), submap
                                // frame, at half the size (a long run keeps hundreds of these)
  int scans_3d = 0;             // 3D scans it received
  MapUpdateTimes update_times;  // its map's update times, summed
};

// One submap (docs/design.md 1.4): its surface, occupancy and incremental
// distance map (SurfaceDistanceMap), in the local odometry frame, and the frame it was created
// in (at the sensor, axes of the local frame). Not thread-safe on its own:
// SubmapManager serialises access.
class Submap {
 public:
  Submap(int id, const Eigen::Vector3d& origin_local, const DistanceMapOptions& options);
  Submap(const Submap&) = delete;
  Submap& operator=(const Submap&) = delete;

  int id() const { return id_; }
  const Eigen::Isometry3d& T_local_submap() const { return T_local_submap_; }
  int scans_3d() const { return scans_3d_; }
  SurfaceDistanceMap& distance_map() { return *map_; }
  const SurfaceDistanceMap& distance_map() const { return *map_; }

  // Queues a 3D scan (local frame) into the distance map and counts it.
  // Throws InputError as DistanceMap::InsertScan.
  void Insert(std::vector<Eigen::Vector3f> points_local, const Eigen::Vector3f& sensor_origin_local);
  // Waits for pending updates, then hands over the surface and drops the
  // live map. The submap must not be used afterwards.
  RetiredSubmap Retire();

 private:
  int id_;
  Eigen::Isometry3d T_local_submap_;
  int scans_3d_ = 0;
  std::unique_ptr<SurfaceDistanceMap> map_;
};

}  // namespace unimap::map
