#pragma once
// The mapping outputs of `unimap run`: the optimised trajectory (TUM and
// KITTI), the map (PCD, PLY, OctoMap) and the mapper's counts for run.json.
#include <filesystem>
#include <vector>

#include "JsonObject.hpp"
#include "pipeline/Mapper.hpp"
#include "unimap/StampedPose.hpp"

namespace unimap::cli {

// Settings of the written map.
struct MapOutputOptions {
  double map_voxel_m = 0.1;         // map.pcd / map.ply keep one point per voxel of this edge (m)
  double octree_resolution_m = 0.1;  // voxel edge of map.bt (m)
};

// Writes out_dir/trajectory.tum and trajectory_kitti.txt (the optimised
// trajectory), map.pcd, map.ply and map.bt, each atomically; returns the
// mapper's counts and the file names as run.json's "mapping" object.
// Throws unimap::Error when a file cannot be written.
JsonObject WriteMapOutputs(const std::filesystem::path& out_dir, const pipeline::Mapper& mapper,
                           const MapOutputOptions& options);

// Position errors (start-anchored on the first odometry pose's position and
// heading, eval::AnchorTransform) of the odometry and the optimised
// trajectories against the truth at time_s (the first loop closure), as
// {"time_s", "odometry": {...}, "optimized": {...}} with
// "height_error_m" (|dz|) and "position_error_m"; an empty object when no
// pose lies within 0.1 s of time_s.
JsonObject LoopPointErrors(const std::vector<StampedPose>& odometry, const std::vector<StampedPose>& optimized,
                           const std::vector<StampedPose>& truth, double time_s);

}  // namespace unimap::cli
