#pragma once
// How a run reports the map voxel it chose for the scene (pipeline::SceneVoxel).
#include <string>

#include "Json.hpp"
#include "pipeline/SceneScale.hpp"
#include "unimap/Platform.hpp"

namespace unimap::cli {

// The line `unimap run` prints: the voxel, the platform's, and why.
std::string SceneVoxelLine(const Platform& platform, const pipeline::SceneScale& scene, double voxel_m);

// run.json's "scene_scale": median range, returns, scans, the platform's
// voxel, the voxel used and the limit that chose it.
Json SceneScaleJson(const Platform& platform, const pipeline::SceneScale& scene, double voxel_m);

}  // namespace unimap::cli
