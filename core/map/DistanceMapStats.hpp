#pragma once
#include <cstddef>
#include <cstdint>

namespace unimap::map {

// Counters and last-update timings of a DistanceMap (for logs and benchmarks).
struct DistanceMapStats {
  std::uint64_t scans_inserted = 0;       // scans integrated into the octree
  std::uint64_t points_inserted = 0;      // finite points of those scans
  std::uint64_t points_skipped = 0;       // non-finite points dropped by InsertScan
  std::uint64_t incremental_updates = 0;  // EDT updates from the octree's changed voxels
  std::uint64_t rebuilds = 0;             // EDT rebuilt over a new box (recentre or growth)
  std::uint64_t budget_shrinks = 0;       // boxes shrunk to fit max_edt_cells
  std::uint64_t failed_updates = 0;       // background updates that threw (see WaitForUpdates)
  std::uint64_t pending_jobs = 0;         // queued requests not yet integrated
  std::size_t edt_cells = 0;              // cells of the current EDT box
  std::size_t field_bytes = 0;            // memory of the published field's grid
  std::size_t surface_voxels = 0;         // occupied voxels with a sub-voxel surface
  std::size_t surface_bytes = 0;          // approximate memory of those surfaces
  double last_insert_s = 0.0;             // octree insertion time of the last update (wall)
  double last_edt_s = 0.0;                // EDT update or rebuild time of the last update
  double last_export_s = 0.0;             // time to copy the EDT into the published field
};

}  // namespace unimap::map
