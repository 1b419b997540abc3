#pragma once
// The scene's scale, read from the first 3D scan, and the map voxel it asks
// for (docs/mapping.md, "Seventh round: the map's voxel follows the scene's scale").
#include <cstddef>
#include <vector>

#include "io/DatasetReader.hpp"
#include "io/ScanRecord.hpp"

namespace unimap::pipeline {

// At most this many map voxels across the scene's median range: the scenes
// the fixed VLP-16, rotating Hokuyo, rotating VLP-16 and HDL-64 files were
// made for span 4-34 of their voxels, the patio with the fixed VLP-16 92
// (docs/mapping.md, "Seventh round"); a scene spanning more gets a coarser
// voxel instead of a map whose upkeep grows with the square of the span.
constexpr double kMaxVoxelsAcrossScene = 40.0;
// The largest voxel the scene may choose: CoreParameters' largest
// distance_map_resolution_m (m).
constexpr double kMaxSceneVoxelM = 2.0;

struct SceneScale {
  double median_range_m = 0.0;  // median range of the scans' returns (0 without any)
  std::size_t returns = 0;      // returns counted (finite, within a line's valid range, range > 0)
  std::size_t scans = 0;        // scans they came from
};

// The median range over every return of the scans (ranges are frame-free,
// so neither deskewing nor the encoder is needed).
SceneScale MeasureSceneScale(const std::vector<io::ScanRecord>& scans);

// The scene scale of the first `scans` scans a reader holds (a reader
// opened for this alone: the scans are consumed). A record the reader
// rejects ends the probe with the scans read before it (the run that
// follows reports the record as it always does).
SceneScale ReadSceneScale(io::DatasetReader& reader, int scans);

// The platform's voxel times the smallest whole factor k >= 1 for which the
// median range spans at most max_voxels_across voxels:
// k = max(1, ceil(median_range_m / (max_voxels_across * platform_voxel_m))),
// at most the largest factor whose voxel is <= max_voxel_m. A median range
// of 0 (no returns) or k = 1 returns platform_voxel_m unchanged.
double SceneVoxel(double platform_voxel_m, double median_range_m, double max_voxels_across, double max_voxel_m);

}  // namespace unimap::pipeline
