#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <utility>
#include <vector>

#include <tsl/robin_map.h>
#include <Eigen/Core>

#include "map/DistanceField.hpp"
#include "map/DistanceMapOptions.hpp"
#include "map/RayWalk.hpp"
#include "map/SurfacePoints.hpp"

namespace unimap::map {

// What a SurfaceDistanceLayer did so far.
struct SurfaceDistanceCounts {
  std::uint64_t points_added = 0;         // returns integrated into the surface elements
  std::uint64_t points_coarse = 0;        // of those, kept in coarse cells (DistanceMapOptions::coarse_beyond_m)
  std::uint64_t points_out_of_range = 0;  // outside the key range: dropped
  std::uint64_t waves = 0;                // surface voxels whose nearest-voxel waves ran (new or back)
  std::uint64_t cells_claimed = 0;        // cells the waves and refills gave a new nearest voxel
  std::uint64_t misses = 0;               // surface voxels a scan saw through (occupancy lowered)
  std::uint64_t voxels_cleared = 0;       // surface voxels that became free (their cells refilled)
  std::uint64_t blocks_computed = 0;      // blocks whose distances were (re)computed at export
  std::size_t elements = 0;               // voxels with a surface element (occupied or not)
  std::size_t occupied = 0;               // of those, occupied now
  std::size_t blocks = 0;                 // distance blocks allocated
  double surface_s = 0.0;                 // wall time: returns into elements, occupancy, carving
  double carve_s = 0.0;                   // of which carving (the rays)
  double distance_s = 0.0;                // wall time: waves, refills and block updates
  double export_s = 0.0;                  // wall time: assembling exported fields
};

// The surface of a map and the distances to it, kept up to date at the cost
// of what changed (docs/design.md 1.4).
//
// Surface: returns go into per-voxel surface elements (SurfacePoints: mean,
// plane, view); each voxel keeps an occupancy log-odds (OctoMap's model and
// DistanceMapOptions' probabilities): a return is a hit, once per scan; an
// occupied voxel that a ray from the sensor to a return of a later scan
// crosses (before the return's voxel) is a miss, once per scan (OctoMap's
// insertion with clear_occupied_only). Only occupied voxels are surface.
// Rays are walked voxel by voxel only through blocks holding an occupied
// voxel: free space costs one look-up per block.
//
// Distances: in blocks of DistanceField::kBlockEdge^3 cells allocated near
// the surface, each cell keeps its nearest occupied voxel by voxel centre
// (the transform DynamicEDT3D computes: 6-neighbour breadth-first waves from
// each newly occupied voxel that stop where cells are nearer to another;
// when a voxel becomes free, its cells are refilled from the voxels around
// them) and, for export, the distance from the cell's centre to that
// voxel's element. A cell's distance is recomputed when it gets a new
// nearest voxel or that voxel's element changes by more than
// kMoveTolerance (its block is copied with those cells recomputed).
// Distances are unsigned (as odometry reads them). Export() shares the
// blocks unchanged since the previous export.
//
// Voxels are named by 16-bit keys per axis (floor(p / resolution) + 32768,
// as OctoMap's): the map spans +-32768 voxels around the origin; returns
// outside are dropped and counted. Not thread-safe (SurfaceDistanceMap
// serialises it).
class SurfaceDistanceLayer {
 public:
  // The distances of the cells an element is nearest to are recomputed
  // when it has changed by more than this many voxels since they were:
  // |mean move| + SurfacePoints::kPatchRadius |normal turn (rad)|, the most
  // any point of its surface disk moved (a bound on every distance change).
  static constexpr float kMoveTolerance = 0.1f;

  // options: resolution, clamp, occupancy probabilities, insertion range,
  // raycast_free_space (carving on or off), compute_distances (false:
  // elements and occupancy only, until EnableDistances()).
  explicit SurfaceDistanceLayer(const DistanceMapOptions& options);
  ~SurfaceDistanceLayer();
  SurfaceDistanceLayer(const SurfaceDistanceLayer&) = delete;
  SurfaceDistanceLayer& operator=(const SurfaceDistanceLayer&) = delete;

  // Integrates the returns (finite, map frame) seen from sensor_map: hits,
  // then misses of the occupied voxels the scan saw through, then (with
  // distances on) the waves, refills and marks of what changed.
  void Insert(const std::vector<Eigen::Vector3f>& points_map, const Eigen::Vector3f& sensor_map);
  // Turns the distances on: every occupied voxel's wave once.
  void EnableDistances();
  bool distances() const { return distances_; }

  // The distance field over the blocks within half_range_m of center_map
  // (every block when half_range_m <= 0), tagged with sequence; blocks
  // unchanged since the previous export are shared with it.
  std::shared_ptr<const DistanceField> Export(const Eigen::Vector3f& center_map, double half_range_m,
                                              std::uint64_t sequence);

  // Centres of the occupied voxels (map frame), in key order.
  std::vector<Eigen::Vector3f> VoxelCenters() const;
  // The mean of the returns in each occupied voxel (map frame), in key
  // order: where the surface is, not where the voxel's centre happens to be.
  // A planar coarse cell (DistanceMapOptions::coarse_beyond_m) gives
  // kCoarseCell^2 points of its plane a voxel apart around its mean.
  std::vector<Eigen::Vector3f> SurfaceMeans() const;
  const SurfacePoints& surfaces() const { return surfaces_; }
  SurfaceDistanceCounts counts() const;

 private:
  struct WorkBlock;
  using KeyHash = SurfacePoints::KeyHash;
  // A voxel that holds returns.
  struct Site {
    Eigen::Vector3i key = Eigen::Vector3i::Zero();
    const SurfacePoints::Element* element = nullptr;  // the live element (SurfacePoints keeps it)
    SurfacePoints::Element marked;                    // as of the last time its blocks were marked
    float log_odds = 0.0f;                            // occupancy
    bool occupied = false;                            // log_odds > 0 (and counted as surface)
    bool waved = false;                               // owns cells (distances on, occupied)
    std::uint64_t missed_in = 0;                      // the last scan whose rays crossed it
    std::vector<WorkBlock*> blocks;                   // blocks where it was ever nearest to a cell
  };

  bool KeyOf(const Eigen::Vector3f& p_map, Eigen::Vector3i* key) const;
  Eigen::Vector3f Center(const Eigen::Vector3i& key) const;
  WorkBlock* BlockAt(const Eigen::Vector3i& key, bool create);
  // The misses of the occupied voxels the rays of a scan (to the sites of
  // its returns, ends, from sensor_map) cross; *freed receives those that
  // became free.
  void Carve(const std::vector<Site*>& ends, const Eigen::Vector3f& sensor_map, std::vector<Site*>* freed);
  // True when a ray from sensor_map to the return whose voxel centre is
  // end_voxel_center_map (standing for a cell of end_scale voxels) passes
  // through site's surface (a miss), not beside it.
  bool RayCrossesSurface(const Site& site, const Eigen::Vector3f& sensor_map,
                         const Eigen::Vector3f& end_voxel_center_map, float end_scale) const;
  // Marks the occupied voxel key as hit or missed by the current scan in
  // its block's masks (BlockMasks::settled): Carve's rays skip it.
  void Settle(const Eigen::Vector3i& key);
  // Sets or clears site's bit in the occupancy masks (a block's entry stays
  // when its last bit is cleared: Carve erases emptied entries when done).
  void SetOccupied(Site* site, bool occupied);
  // A cell queued for Spread(): it is nearest to site (so far); block holds it.
  struct WaveFront {
    Eigen::Vector3i cell;
    std::uint16_t sq;  // its squared distance from site's voxel (voxels^2)
    Site* site;
    WorkBlock* block;
  };
  // Claims site's own voxel and queues it: Spread() claims cells from it
  // outwards (see the class comment).
  void Wave(Site* site);
  // Releases the cells of a site that became free and queues their
  // neighbours: Spread() gives them to their next nearest occupied voxels.
  void Refill(Site* site);
  // Claims, nearest first, the neighbours of queued cells that are nearer
  // to the queued cell's voxel than to their own, until no claim is left.
  void Spread();
  // Queues a cell at squared distance sq (voxels^2) from site's voxel.
  void Push(const Eigen::Vector3i& cell, Site* site, WorkBlock* block, int sq);
  // Adds block to the blocks where site is nearest to a cell.
  static void Record(Site* site, WorkBlock* block);
  void MarkIfChanged(Site* site, bool always);
  void Compute(WorkBlock* block, const Eigen::Vector3i& block_key);

  DistanceMapOptions options_;
  float clamp_m_;
  int reach_;            // a wave goes at most this many voxels from its voxel (the clamp, rounded up, plus one)
  float log_odds_hit_;   // occupancy update of a return
  float log_odds_miss_;  // of a see-through (negative)
  float log_odds_min_;
  float log_odds_max_;
  bool distances_;
  SurfacePoints surfaces_;
  std::deque<Site> site_store_;                                                // every site (stable addresses)
  tsl::robin_map<std::uint64_t, Site*, KeyHash> sites_;                        // by packed voxel key
  tsl::robin_map<std::uint64_t, std::unique_ptr<WorkBlock>, KeyHash> blocks_;  // by packed block key
  std::size_t occupied_ = 0;                                                   // sites occupied now
  Eigen::Vector3i block_min_ = Eigen::Vector3i::Constant(1 << 20);             // extent of blocks_
  Eigen::Vector3i block_max_ = Eigen::Vector3i::Constant(-(1 << 20));
  using VoxelMask = std::array<std::uint64_t, DistanceField::kBlockCells / 64>;
  // Per block holding an occupied voxel: which of its voxels are, and which
  // of those the scan being carved has hit or missed already (their
  // Site::missed_in is the scan's), so that later rays skip them without
  // looking their sites up (most rays of a scan cross the same voxels).
  struct BlockMasks {
    VoxelMask occupied{};
    VoxelMask settled{};           // valid when settled_in == scans_
    std::uint64_t settled_in = 0;  // the scan settled refers to
  };
  tsl::robin_map<std::uint64_t, BlockMasks, KeyHash> occupied_masks_;
  std::uint64_t scans_ = 0;  // scans inserted (stamps Site::missed_in)
  // Carve's cache of occupied_masks_ look-ups (valid during one Carve).
  struct MaskCacheEntry {
    std::uint64_t packed_block = ~std::uint64_t{0};  // the block (none)
    BlockOccupancy occupancy;                        // what it holds
    BlockMasks* masks = nullptr;                     // its entry of occupied_masks_ (null: none)
  };
  static constexpr std::size_t kMaskCacheSize = 4096;  // a power of two
  std::vector<MaskCacheEntry> mask_cache_;
  // Spread()'s queue: a bucket per squared distance (voxels^2), each kept
  // between calls to reuse its memory unless it held more than kKeptWaveFronts.
  static constexpr std::size_t kKeptWaveFronts = 1u << 12;
  std::vector<std::vector<WaveFront>> buckets_;
  int next_bucket_ = 0;  // the bucket Spread() works on (pushes go there or later)
  SurfaceDistanceCounts counts_;
};

}  // namespace unimap::map
