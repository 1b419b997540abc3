#pragma once
#include <cstdint>
#include <memory>
#include <unordered_set>
#include <vector>

#include <Eigen/Core>

#include "map/DistanceMapOptions.hpp"
#include "map/KeyBox.hpp"
#include "map/SurfacePoints.hpp"

namespace octomap {
class OcTree;
}

namespace unimap::map {

// The occupancy octree (OctoMap) with the sensor model of DistanceMapOptions,
// and the voxel/key arithmetic the distance map needs. With
// options.subvoxel_surfaces it also keeps the returns' surface inside every
// occupied voxel (SurfacePoints), forgotten when the voxel turns free.
// Change detection is left to the distance transform (EdtRegion). Not
// thread-safe.
class OccupancyTree {
 public:
  using KeySetType = std::unordered_set<std::uint64_t>;  // packed voxel keys
  // An empty tree at options.resolution_m.
  explicit OccupancyTree(const DistanceMapOptions& options);
  // Adopts tree (its resolution wins over options.resolution_m) and applies
  // the occupancy probabilities of options. Throws InputError on null or
  // when its occupied leaves cover more than options.max_occupied_voxels
  // (a cap of 5e7, 2 GB, let a fuzzed tree run out of memory:
  // tests/fuzz/regressions/bt/oom-expanded-occupied-set.bt).
  OccupancyTree(std::unique_ptr<octomap::OcTree> tree, const DistanceMapOptions& options);
  ~OccupancyTree();
  OccupancyTree(const OccupancyTree&) = delete;
  OccupancyTree& operator=(const OccupancyTree&) = delete;

  // Integrates one scan (finite points and origin, map frame): every return
  // within max_insert_range_m is a hit on its voxel; rays from the origin
  // (cut at that range) lower the voxels they cross as the options say, a
  // voxel hit in the same scan is never lowered by it. Returns the keys box of
  // the hits (the only voxels that can have become occupied).
  KeyBox Insert(const std::vector<Eigen::Vector3f>& points_map, const Eigen::Vector3f& origin_map);
  // Marks the voxel of every (finite) point occupied at the upper clamp, no
  // ray casting: for prior maps given as point clouds (their surfaces have
  // no view direction, so they are never signed).
  void MarkOccupied(const std::vector<Eigen::Vector3f>& points_map);

  // Key of the voxel containing p (p within +-HalfRangeM()).
  Eigen::Vector3i KeyOf(const Eigen::Vector3f& p_map) const;
  // Centre of the voxel with key.
  Eigen::Vector3f KeyCenter(const Eigen::Vector3i& key) const;
  // Box of the occupied voxels inside within (empty when there are none).
  KeyBox OccupiedExtent(const KeyBox& within) const;
  // Centres of all occupied voxels (pruned nodes expanded to voxels).
  std::vector<Eigen::Vector3f> OccupiedVoxelCenters() const;

  double resolution_m() const { return resolution_m_; }
  // Coordinates must stay within +- this (16-bit octree keys).
  double HalfRangeM() const { return HalfRangeM(resolution_m_); }
  // The same for any resolution.
  static double HalfRangeM(double resolution_m) { return 32767.0 * resolution_m; }
  octomap::OcTree& tree() { return *tree_; }
  const octomap::OcTree& tree() const { return *tree_; }
  // Sub-voxel surfaces of the occupied voxels; null without
  // options.subvoxel_surfaces. Voxels occupied by a loaded octree have none.
  const SurfacePoints* surfaces() const { return surfaces_.get(); }

 private:
  void ApplySensorModel();
  // Standard OctoMap insertion (clear_occupied_only off).
  KeyBox InsertWithOctomap(const std::vector<Eigen::Vector3f>& points_map, const Eigen::Vector3f& origin_map);
  // Lowers the occupied voxels the rays to ends cross (clear_occupied_only).
  void ClearOccupiedAlongRays(const Eigen::Vector3f& origin_map, const std::vector<Eigen::Vector3f>& ends_map,
                              const KeySetType& hits);
  // Applies one hit or miss to key and keeps occupied_ and surfaces_ in step.
  void UpdateVoxel(const Eigen::Vector3i& key, bool hit);
  // Adds the returns within range to surfaces_ (sensor_map null: unknown).
  void AddSurfacePoints(const std::vector<Eigen::Vector3f>& points_map, const Eigen::Vector3f* sensor_map);
  // Refreshes the surface of key when its voxel is occupied, else forgets it.
  void SyncSurface(const Eigen::Vector3i& key);

  DistanceMapOptions options_;
  std::unique_ptr<octomap::OcTree> tree_;
  double resolution_m_;
  bool tracks_occupied_;  // occupied_ is maintained (clear_occupied_only ray casting)
  // Packed keys of the occupied voxels, so rays test voxels without tree walks.
  KeySetType occupied_;
  std::unique_ptr<SurfacePoints> surfaces_;  // null without options.subvoxel_surfaces
};

}  // namespace unimap::map
