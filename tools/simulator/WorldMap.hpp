#pragma once
#include <cstddef>
#include <filesystem>

#include "Scenario.hpp"
#include "SurfaceSampler.hpp"
#include "TrajectoryViewpoints.hpp"
#include "unimap/Platform.hpp"

namespace unimap::sim {

// Name of the true map inside a simulated dataset folder.
inline constexpr const char* kWorldMapFile = "world_map.pcd";

// How the true map is sampled (docs/simulation.md, "True map").
struct WorldMapOptions {
  SurfaceSamplerOptions sampler;  // rays per viewpoint, voxel; max_range_m is replaced by the payload's
  ViewpointOptions viewpoints;    // viewpoint spacing along the trajectory
};

// What WriteWorldMap did.
struct WorldMapSummary {
  std::filesystem::path file;  // the PCD written
  std::size_t viewpoints = 0;  // ray origins along the true trajectory
  std::size_t points = 0;      // surface points written (one per voxel)
  double max_range_m = 0.0;    // ray length used
  double wall_s = 0.0;         // wall-clock seconds taken
};

// The payload's ray length for the true map: its `lidar.max_range_m` when it
// has one, else its distance-map max range.
double WorldMapRange(const Platform& platform);

// Writes the true map of a scenario's world as seen from its trajectory over
// [0, duration_s]: SurfaceSampler hits from TrajectoryViewpoints (body
// positions), rays up to WorldMapRange(platform), as a binary PCD (x y z,
// world frame = the ground truth's frame) at file, atomically. Throws
// ConfigError for the scenario's world or trajectory, InputError when the
// file cannot be written.
WorldMapSummary WriteWorldMap(const Scenario& scenario, const Platform& platform, double duration_s,
                              const std::filesystem::path& file, WorldMapOptions options = {});

}  // namespace unimap::sim
